use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", mjcf = "../../../../robots/ur5_mjcf.xml")]
struct Robot;

fn main() {}
