//! Derived code that must compile, and compute right, whatever the robot's shape, whatever the
//! struct's generics are called and whatever is in scope where it is derived (issue 13: a one-row
//! DH table derived into code that did not type-check; a generic parameter `T` collided with the
//! generated code's own `T`). Each struct below is a case; the crate failing to build is the
//! failure, and each is also checked against the runtime reference through the trait.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::marker::PhantomData;

use kinematics::{AGREEMENT_TOLERANCE, Kinematics, Pose};

/// One DH row: one link below the base.
#[derive(Kinematics)]
#[kinematics(dh = "tests/emitted/one_row.toml", tip = "link1", positions, scalars(f64, f32))]
struct OneRow;

/// The same tip as a list of one.
#[derive(Kinematics)]
#[kinematics(dh = "tests/emitted/one_row.toml", tips("link1"), positions)]
struct OneRowTips;

/// One row, no tip: only the all-links functions.
#[derive(Kinematics)]
#[kinematics(dh = "tests/emitted/one_row.toml", positions)]
struct OneRowLinks;

/// Zero degrees of freedom: fixed joints only.
#[derive(Kinematics)]
#[kinematics(urdf = "tests/emitted/fixed_only.urdf", tip = "tool", positions, scalars(f64, f32))]
struct ZeroDof;

/// A robot that is only its base: no link to compute.
#[derive(Kinematics)]
#[kinematics(urdf = "tests/emitted/single_link.urdf", positions)]
struct OnlyBase;

/// The tip is the base.
#[derive(Kinematics)]
#[kinematics(urdf = "tests/emitted/fixed_only.urdf", base = "tool", tip = "tool", positions)]
struct BaseIsTip;

/// The tip above the base (the path goes up).
#[derive(Kinematics)]
#[kinematics(urdf = "tests/emitted/fixed_only.urdf", base = "tool", tip = "base")]
struct Upward;

/// Tips with no moving joint between them and the base, on a robot that has joints elsewhere.
#[derive(Kinematics)]
#[kinematics(urdf = "tests/emitted/arm_with_flange.urdf", base = "fore", tips("fore", "flange"), positions)]
struct NoJointBetween;

/// A generic parameter named `T`, as the generated code's scalar once was.
#[derive(Kinematics)]
#[kinematics(dh = "tests/emitted/one_row.toml", tip = "link1", scalars(f64, f32))]
struct GenericT<T>(PhantomData<T>);

/// A lifetime, a bounded type, a const generic and a where clause.
#[derive(Kinematics)]
#[kinematics(urdf = "tests/emitted/arm_with_flange.urdf", tip = "flange", positions, scalars(f32, f64))]
struct Everything<'a, T: Clone, const N: usize>
where
    T: Default,
{
    _borrowed: PhantomData<&'a [T; N]>,
}

/// Collision checking on a struct with a lifetime, a bounded type, a const generic and a where
/// clause: the `Collision<N>` impl carries them as `Kinematics`' does.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5_spherized.urdf", collision)]
struct CollidingGeneric<'a, T: Clone, const N: usize>
where
    T: Default,
{
    _borrowed: PhantomData<&'a [T; N]>,
}

#[test]
fn a_generic_struct_with_collision_implements_the_collision_trait() {
    // Through the trait, as generic code reaches it: the description's 40 spheres, their links,
    // and a configuration that is not finite never free.
    fn survey<R: kinematics::collision::Collision<6>>() -> (usize, bool, bool) {
        let on_upper_arm = R::SPHERE_LINKS.contains(&"upper_arm_link");
        (R::SPHERE_RADII.len(), on_upper_arm, R::self_collides(&[f64::NAN; 6]))
    }
    assert_eq!(survey::<CollidingGeneric<'static, u8, 3>>(), (40, true, true));
}

/// Parameters named after the types the generated code uses.
#[derive(Kinematics)]
#[kinematics(urdf = "tests/emitted/arm_with_flange.urdf", tips("fore", "flange"))]
struct NamedLikeOurs<Real, Pose, K: Copy = u8>(PhantomData<(Real, Pose, K)>);

/// Names of the user's own where the derive expands: a `Pose`, a `Real`, a module `kinematics`,
/// `Ok`, `Result` and `Option` of its own.
mod crowded {
    #![allow(dead_code, non_camel_case_types, clippy::upper_case_acronyms)]
    pub struct Pose;
    pub trait Real {}
    pub mod kinematics {}
    pub struct Ok;
    pub struct Option;
    pub type Result = ();
    pub struct T;

    #[derive(::kinematics::Kinematics)]
    #[kinematics(urdf = "tests/emitted/arm_with_flange.urdf", tip = "flange", positions, scalars(f64, f32))]
    pub struct InScope;
}

/// The poses every compiled robot gives through the trait agree with its reference at `q`.
fn agrees<R: kinematics::ReferenceModel>(q: &[f64]) {
    let reference = R::reference().unwrap();
    let blank = Pose { rotation: [[f64::NAN; 3]; 3], translation: [f64::NAN; 3] };
    for (names, compute) in
        [(R::LINK_NAMES, R::link_poses_into as fn(&[f64], &mut [Pose<f64>]) -> _), (R::TIPS, R::tip_poses_into)]
    {
        let mut out = vec![blank; names.len()];
        compute(q, &mut out).unwrap();
        for (name, pose) in names.iter().zip(&out) {
            let expected = reference.relative_pose(q, R::BASE, name).unwrap();
            let deviation = pose.deviation(&expected, 1.0);
            assert!(deviation <= AGREEMENT_TOLERANCE, "{}: `{name}` off by {deviation:e}", R::ROBOT);
        }
    }
}

#[test]
fn one_row() {
    let q = [0.7];
    let pose = OneRow::tip_pose(&q);
    assert_eq!(OneRow::link_poses(&q), [pose]);
    assert_eq!(OneRow::tip_position(&q), pose.translation);
    assert_eq!(OneRow::link_positions(&q), [pose.translation]);
    let pose32 = OneRow::tip_pose_f32(&[0.7]);
    assert!((f64::from(pose32.translation[0]) - pose.translation[0]).abs() < 1e-6);
    assert_eq!(OneRow::link_poses_f32(&[0.7]).len(), 1);
    assert_eq!(OneRowTips::tip_pose(&q), pose);
    assert_eq!(OneRowTips::tip_position(&q), pose.translation);
    assert_eq!(OneRowLinks::link_poses(&q), [pose]);
    assert_eq!(OneRowLinks::TIPS.len(), 0);
    agrees::<OneRow>(&q);
    agrees::<OneRowTips>(&q);
    agrees::<OneRowLinks>(&q);
}

#[test]
fn zero_dof_and_degenerate_tips() {
    let pose = ZeroDof::tip_pose(&[]);
    assert_eq!(ZeroDof::DOF, 0);
    assert_eq!(ZeroDof::link_poses(&[]).len(), 2);
    assert_eq!(ZeroDof::tip_position(&[]), pose.translation);
    assert_eq!(ZeroDof::tip_pose_f32(&[]).translation.map(f64::from), pose.translation.map(|x| f64::from(x as f32)));
    assert_eq!(OnlyBase::link_poses(&[]), []);
    assert_eq!(OnlyBase::link_positions(&[]), [[0.0; 3]; 0]);
    let identity = BaseIsTip::tip_pose(&[]);
    assert_eq!(identity.rotation, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
    assert_eq!(BaseIsTip::tip_position(&[]), [0.0; 3]);
    let up = Upward::tip_pose(&[]);
    assert!(up.translation.iter().any(|x| *x != 0.0));
    let [fore, flange] = NoJointBetween::tip_poses(&[0.3, -0.4]);
    assert_eq!(fore.translation, [0.0; 3]);
    assert_eq!(NoJointBetween::tip_positions(&[0.3, -0.4]), [fore.translation, flange.translation]);
    agrees::<ZeroDof>(&[]);
    agrees::<OnlyBase>(&[]);
    agrees::<BaseIsTip>(&[]);
    agrees::<Upward>(&[]);
    agrees::<NoJointBetween>(&[0.3, -0.4]);
}

#[test]
fn any_generics() {
    let q = [0.7];
    assert_eq!(GenericT::<String>::tip_pose(&q), OneRow::tip_pose(&q));
    assert_eq!(GenericT::<String>::tip_pose_f32(&[0.7]), OneRow::tip_pose_f32(&[0.7]));
    agrees::<GenericT<Vec<u8>>>(&q);
    let q = [0.3, -0.4];
    let flange = Everything::<'static, u8, 3>::tip_pose(&q);
    let position = Everything::<u8, 3>::tip_position(&q);
    assert!((0..3).all(|i| (position[i] - flange.translation[i]).abs() < 1e-15), "{position:?}");
    assert_eq!(Everything::<u8, 3>::tip_pose_f32(&[0.3, -0.4]).rotation.len(), 3);
    agrees::<Everything<'static, String, 0>>(&q);
    let [_, also_flange] = NamedLikeOurs::<f64, f32>::tip_poses(&q);
    assert!((0..3).all(|i| (also_flange.translation[i] - flange.translation[i]).abs() < 1e-15));
    agrees::<NamedLikeOurs<(), ()>>(&q);
}

#[test]
fn names_in_scope_do_not_matter() {
    let q = [0.3, -0.4];
    assert_eq!(crowded::InScope::tip_pose(&q), Everything::<u8, 3>::tip_pose(&q));
    agrees::<crowded::InScope>(&q);
}
