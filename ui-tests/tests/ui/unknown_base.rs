use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dh = "../../../../robots/ur5.toml", base = "world", tip = "wrist_3_link")]
struct Robot;

fn main() {}
