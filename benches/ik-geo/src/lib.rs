//! Nothing here: the crate is its benchmark, `benches/peers.rs` (`bash benches/ik-geo/run.sh`).
//! Cargo wants a library or a binary in every package, so this empty library is the one.
