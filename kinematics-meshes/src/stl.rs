//! STL, ASCII and binary: mesh-loader reads both (`src/stl/mod.rs`: a file starting with `solid`
//! is tried as ASCII first, then as binary), after one check of ours on binary files.

use crate::merge::Merged;

/// A binary STL's header: 80 bytes, then the triangle count.
const HEADER: usize = 80;
/// Bytes per triangle: a normal, three corners, two attribute bytes.
const TRIANGLE: u64 = 50;

/// Reads the STL document `bytes` into `merged`.
pub(crate) fn read(bytes: &[u8], merged: &mut Merged) -> Result<(), String> {
    check_count(bytes)?;
    let scene = mesh_loader::stl::from_slice(bytes).map_err(|e| e.to_string())?;
    scene.meshes.iter().try_for_each(|m| merged.add(&m.vertices, &m.faces, None))
}

/// Refuses a binary file shorter than its header's triangle count says: a truncated file.
/// mesh-loader reads as many triangles as the length holds, whatever the count (some exporters
/// write a wrong one), so a file cut at a triangle's end would lose its tail without a word; a
/// count *below* the length is accepted, as there. (assimp, which ROS's viewers use, refuses the
/// short file too.)
fn check_count(bytes: &[u8]) -> Result<(), String> {
    let Some(count) = bytes.get(HEADER..HEADER + 4) else { return Ok(()) };
    if is_ascii_stl(bytes) {
        return Ok(());
    }
    let count = u64::from(u32::from_le_bytes([count[0], count[1], count[2], count[3]]));
    let held = (bytes.len() as u64 - (HEADER as u64 + 4)) / TRIANGLE;
    if count > held {
        return Err(format!("it is cut short: its header says {count} triangles and it holds {held}"));
    }
    Ok(())
}

/// Whether the file is text beginning with `solid`: what mesh-loader reads as ASCII. A binary
/// file's count and floats hold bytes no text has.
fn is_ascii_stl(bytes: &[u8]) -> bool {
    let text = bytes.iter().all(|&b| b.is_ascii_graphic() || b.is_ascii_whitespace() || b == b'\x0B');
    text && bytes.trim_ascii_start().starts_with(b"solid")
}
