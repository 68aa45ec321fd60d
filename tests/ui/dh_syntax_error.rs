use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dh = "../../../../tests/ui/fixtures/bad_row.toml")]
struct Robot;

fn main() {}
