use kinematics::Kinematics;

// A ball joint turns about every axis through its `pos`: an `axis` written on it is refused.
#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../ui-tests/tests/ui/fixtures/mjcf/ball_axis.xml")]
struct WithAxis;

// A `range` that limits a ball joint is a cone limit, which is not modelled: refused, here where
// its default class writes it.
#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../ui-tests/tests/ui/fixtures/mjcf/ball_range.xml")]
struct WithRange;

// An equality couples hinges and slides: one naming a ball joint is refused.
#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../ui-tests/tests/ui/fixtures/mjcf/ball_equality.xml")]
struct Coupled;

fn main() {}
