use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dh = "../../../../ui-tests/tests/ui/fixtures/bad_row.toml")]
struct Robot;

fn main() {}
