//! The trigonometry floors: the sin/cos calls a robot's function makes, and nothing else. Our
//! sin/cos as the generated code calls it (every angle of the function in one `sin_cos_many` call)
//! and std's (`sin_cos` once per angle, as code derived with `trig = "std"` calls it), over as many
//! angles as the compiler counts `sin_cos` pairs. No code calling the routine can beat its floor,
//! so a body's time over its floor is how far it is from the best it could be, and the peers'
//! times over the floor of all links bound the speed-up any such code could show.

use kinematics::{Real, StdTrig};

/// The trigonometry floor with std's `sin_cos`: `n` calls, one per angle, as code derived with
/// `trig = "std"` makes them (each pair folded into one sum so none is optimised away; that costs a
/// multiply-add per pair). The angles are the joint values, cycled: the routine's time does not
/// depend on which angles they are.
#[inline(always)]
pub fn floor_std<T: StdTrig, const N: usize>(q: &[T; N], n: usize) -> T {
    let mut acc = T::from_f64(0.0);
    for i in 0..n {
        let (s, c) = q[i % N].sin_cos_std();
        acc = acc + s * c;
    }
    acc
}

/// The trigonometry floor with our sin/cos, as the generated code calls it: all `n` angles of the
/// function in one `T::sin_cos_many` call (folded like [`floor_std`]), dispatched to the widest
/// instruction set the CPU has, as the generated functions are. `n` is a run-time count
/// (the compiler's), `sin_cos_many` takes it as a constant: one arm per count, chosen by a branch
/// that always goes the same way.
#[inline(always)]
pub fn floor_fast<T: Real, const N: usize>(q: &[T; N], n: usize) -> T {
    #[inline(always)]
    fn many<T: Real, const N: usize, const K: usize>(q: &[T; N]) -> T {
        let (s, c) = T::sin_cos_many::<K>(std::array::from_fn(|i| q[i % N]));
        let mut acc = T::from_f64(0.0);
        for i in 0..K {
            acc = acc + s[i] * c[i];
        }
        acc
    }
    macro_rules! by_count {
        ($($k:literal)*) => {
            match n {
                $($k => many::<T, N, $k>(q),)*
                _ => panic!("no floor for {n} angles: add the count to `floor_fast`"),
            }
        };
    }
    // Dispatched, as the generated functions are: the floor of what they run on this CPU.
    kinematics::dispatch(
        #[inline(always)]
        || by_count!(0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32),
    )
}

/// The `sin_cos` pairs of a robot's tip pose and of all its link poses, as the compiler counts them.
pub fn sin_cos(file: &str, tip: &str) -> (usize, usize) {
    use kinematics_compiler::{Request, compile};
    let path = format!("{}/robots/{file}", env!("CARGO_MANIFEST_DIR"));
    let tree = kinematics::load(path).expect("robot loads");
    let count = |request: &Request| compile(&tree, request).map_or(0, |c| c.op_count().sin_cos);
    (count(&Request::tip(tip)), count(&Request::all_links()))
}
