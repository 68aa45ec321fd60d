use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dh = "../../../../robots/ur5.toml")]
enum Robot { A }

fn main() {}
