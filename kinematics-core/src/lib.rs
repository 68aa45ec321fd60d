//! What generated forward kinematics needs at run time, and nothing else: `#![no_std]`, no
//! allocation.
#![no_std]

pub mod trig;
