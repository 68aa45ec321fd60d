use kinematics::Kinematics;

// A scalar list that names no scalar type.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", tip = "tool0", scalars())]
struct NoScalar;

fn main() {}
