use kinematics::Kinematics;

// Inverse kinematics is the tip's: one tip.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", tips("tool0", "ee_link"), ik)]
struct TwoTips;

// An unknown kind.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", tip = "tool0", ik = "analytic")]
struct UnknownKind;

// A free joint that is not in the chain.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/iiwa14.urdf", tip = "iiwa_link_ee", ik(free = "iiwa_joint_9"))]
struct NoSuchJoint;

// A misspelt kind: the kinds, and the one meant.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", tip = "tool0", ik = "numerc")]
struct MisspeltKind;

fn main() {}
