//! `#[derive(Kinematics)]`: reads a URDF file, an MJCF file or a DH table at compile time and gives the struct its
//! closed-form forward kinematics. A shim: all logic is in `kinematics-derive-core`. Use it through
//! the `kinematics` crate, which re-exports it with the trait of the same name.

use proc_macro::TokenStream;

/// Compiles a robot description into forward kinematics for the annotated struct.
///
/// See the `kinematics` crate for the attribute's keys and what the struct gets.
#[proc_macro_derive(Kinematics, attributes(kinematics))]
pub fn derive_kinematics(input: TokenStream) -> TokenStream {
    kinematics_derive_core::expand(input.into()).into()
}
