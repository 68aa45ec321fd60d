// A generic struct whose description cannot be read: the stub carries the struct's generics.
use std::marker::PhantomData;

use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dh = "robots/no_such_table.toml", tip = "link2")]
struct Arm<'a, T: Clone, const N: usize>
where
    T: Default,
{
    _marker: PhantomData<&'a [T; N]>,
}

fn dof<R: Kinematics>() -> usize {
    R::DOF
}

fn main() {
    let pose = Arm::<'static, u8, 3>::tip_pose(&[0.0, 1.0]);
    let _ = (pose.rotation, dof::<Arm<'static, u8, 3>>());
}
