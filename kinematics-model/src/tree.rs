//! The validated kinematic tree: link and joint arenas in a fixed, documented order.

use std::collections::{BTreeMap, BTreeSet};

use crate::collision::{Shape, TriangleMesh};
use crate::description::{Description, ExcludedPair};
use crate::error::{ModelError, ModelErrors};
use crate::exactness::{ExactAngles, RecognisedAngle};
use crate::joint::{Joint, JointKind, JointMotion, Limits, Link, length, stroke};

/// A mesh file [`KinematicTree::load_meshes`] could not read.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("link `{link}`: mesh `{filename}`: {reason}")]
pub struct MeshLoadError {
    /// The first link that uses it.
    pub link: String,
    /// The file as written.
    pub filename: String,
    /// Why it could not be read.
    pub reason: String,
}

/// Index of a link in [`KinematicTree::links`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct LinkId(pub usize);

/// Index of a joint in [`KinematicTree::joints`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct JointId(pub usize);

/// A validated kinematic tree.
///
/// Valid by construction: exactly one root, every link reached from it by exactly one path, every
/// name unique, every number finite, every moving joint's axis of unit length, limits ordered and
/// mimic joints resolved to an independent source. Later stages therefore have no error path for a
/// bad robot.
///
/// **Order.** Links and joints are stored in depth-first pre-order from the root, visiting a link's
/// child joints in the order the description lists them; so `LinkId(0)` is the root and every
/// joint comes after the joint of its parent link. The degrees of freedom (the entries of `q`) are
/// the moving, non-mimic joints in that same order: for a chain, base to tip; for a DH table, row
/// order.
#[derive(Debug, Clone, PartialEq)]
pub struct KinematicTree {
    pub(crate) name: String,
    pub(crate) links: Vec<Link>,
    pub(crate) joints: Vec<Joint>,
    pub(crate) dof_joints: Vec<JointId>,
    pub(crate) exact_angles: ExactAngles,
    pub(crate) recognised: Vec<RecognisedAngle>,
    /// Fixed joints whose `<mimic>` of another fixed joint was read and had nothing to do.
    pub(crate) vacuous_mimics: Vec<String>,
    /// What the description says that is not applied ([`Description::ignored`]).
    pub(crate) ignored: Vec<String>,
    /// Link pairs the description rules out of collision checking ([`Description::excluded_pairs`]).
    pub(crate) excluded_pairs: Vec<ExcludedPair>,
    /// Each `<inertial>`'s line, by link name ([`Description::inertials`]).
    pub(crate) inertial_lines: Lines,
    /// Links whose mass is left to their geometry ([`Description::inertia_from_geometry`]).
    pub(crate) inertia_from_geometry: Vec<String>,
    /// Links by name, for lookups in O(log n).
    link_index: BTreeMap<String, LinkId>,
    /// Joints by name.
    joint_index: BTreeMap<String, JointId>,
    /// Number of joints from the root to each link.
    depth: Vec<usize>,
}

/// Where elements were written, by name: for messages only. Two trees of one robot are equal
/// wherever their files put its elements (urdf-rs keeps no lines, the built-in reader does), so
/// these compare equal always.
#[derive(Debug, Clone, Default)]
pub(crate) struct Lines(pub(crate) BTreeMap<String, usize>);

impl PartialEq for Lines {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

/// The joints on the path from a base link down to a tip link.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Chain {
    /// The base link.
    pub base: LinkId,
    /// The tip link.
    pub tip: LinkId,
    /// The joints from base to tip, in that order (empty when base is the tip).
    pub joints: Vec<JointId>,
}

impl KinematicTree {
    /// The tree of validated arenas (links and joints in depth-first pre-order, parents first),
    /// with its name indices.
    pub(crate) fn new(name: String, links: Vec<Link>, joints: Vec<Joint>, dof_joints: Vec<JointId>) -> Self {
        let link_index = links.iter().enumerate().map(|(i, l)| (l.name.clone(), LinkId(i))).collect();
        let joint_index = joints.iter().enumerate().map(|(i, j)| (j.name.clone(), JointId(i))).collect();
        let mut depth = vec![0; links.len()];
        // Pre-order: a joint's parent link comes before its child.
        for j in &joints {
            depth[j.child.0] = depth[j.parent.0] + 1;
        }
        KinematicTree {
            name,
            links,
            joints,
            dof_joints,
            exact_angles: ExactAngles::Off,
            recognised: Vec::new(),
            vacuous_mimics: Vec::new(),
            ignored: Vec::new(),
            excluded_pairs: Vec::new(),
            inertial_lines: Lines::default(),
            inertia_from_geometry: Vec::new(),
            link_index,
            joint_index,
            depth,
        }
    }

    /// Checks every rule against `description` and builds the tree, or returns every fault found;
    /// decimal angles are read by the default exactness policy ([`ExactAngles::default`]).
    pub fn from_description(description: &Description) -> Result<Self, ModelErrors> {
        Self::from_description_with(description, ExactAngles::default())
    }

    /// [`KinematicTree::from_description`] with the exactness policy `exact_angles`: the angles it
    /// recognises as exact multiples of pi/2 are that multiple in the tree, for the runtime and
    /// the compiler alike ([`KinematicTree::recognised_angles`] lists them).
    pub fn from_description_with(description: &Description, exact_angles: ExactAngles) -> Result<Self, ModelErrors> {
        let mut description = description.clone();
        let recognised = crate::exactness::recognise(&mut description, exact_angles);
        let mut tree = crate::validate::build(&description)?;
        tree.exact_angles = exact_angles;
        tree.recognised = recognised;
        Ok(tree)
    }

    /// The exactness policy the tree was built with.
    pub fn exact_angles(&self) -> ExactAngles {
        self.exact_angles
    }

    /// Every angle the exactness policy changed, in description order.
    pub fn recognised_angles(&self) -> &[RecognisedAngle] {
        &self.recognised
    }

    /// Fixed joints whose `<mimic>` names another fixed joint: both say the joint does not move,
    /// so the mimic has nothing to do (urdfdom reads such files, VAMP's Panda has one); listed
    /// here rather than applied or refused. A fixed joint that mimics a moving one is refused.
    pub fn vacuous_mimics(&self) -> &[String] {
        &self.vacuous_mimics
    }

    /// What the description says that is not applied, each naming its element and line: an
    /// MJCF `<equality>` other than a linear joint coupling (connect, weld, a joint polynomial of
    /// higher degree, an inactive constraint). Empty for URDF and DH tables.
    pub fn ignored(&self) -> &[String] {
        &self.ignored
    }

    /// The link pairs the description rules out of collision checking, each with its reason (an
    /// MJCF `<contact><exclude>`, or geoms whose `contype` and `conaffinity` never meet). Empty
    /// for URDF (an SRDF says this for a URDF) and DH tables.
    pub fn excluded_pairs(&self) -> &[ExcludedPair] {
        &self.excluded_pairs
    }

    /// The line of link `link`'s `<inertial>`, when read from a file.
    pub fn inertial_line(&self, link: &str) -> Option<usize> {
        self.inertial_lines.0.get(link).copied()
    }

    /// Links whose mass the description leaves to be inferred from their geometry (MJCF bodies
    /// with geoms and no `<inertial>`): dynamics refuse them. Empty for URDF and DH tables.
    pub fn inertia_from_geometry(&self) -> &[String] {
        &self.inertia_from_geometry
    }

    /// Every link, in tree order, whose mass the dynamics cannot take: one whose mass is left to
    /// its geometry, or whose `<inertial>` breaks a rigid body's rules ([`Inertial::fault`]; the
    /// triangle inequality only unless `as_written`), each with the line of its `<inertial>`.
    ///
    /// [`Inertial::fault`]: crate::inertia::Inertial::fault
    pub fn inertia_refusals(&self, as_written: bool) -> Vec<crate::inertia::InertiaRefusal> {
        use crate::inertia::InertiaRefusal;
        let mut refusals = Vec::new();
        for link in &self.links {
            if self.inertia_from_geometry.contains(&link.name) {
                refusals.push(InertiaRefusal::FromGeometry { link: link.name.clone() });
            } else if let Some(fault) = link.inertial.as_ref().and_then(|i| i.fault(as_written)) {
                let line = self.inertial_line(&link.name);
                refusals.push(InertiaRefusal::Fault { link: link.name.clone(), line, fault });
            }
        }
        refusals
    }

    /// [`KinematicTree::excluded_pairs`] as links, each `(a, b)` with `a` before `b` in tree order.
    pub fn excluded_link_pairs(&self) -> BTreeSet<(LinkId, LinkId)> {
        self.excluded_pairs
            .iter()
            .filter_map(|p| {
                let (a, b) = (self.link_id(&p.link1)?, self.link_id(&p.link2)?);
                Some((a.min(b), a.max(b)))
            })
            .collect()
    }

    /// Robot name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The root link (always `LinkId(0)`).
    pub fn root(&self) -> LinkId {
        LinkId(0)
    }

    /// All links, in depth-first order from the root.
    pub fn links(&self) -> &[Link] {
        &self.links
    }

    /// All joints, in depth-first order from the root.
    pub fn joints(&self) -> &[Joint] {
        &self.joints
    }

    /// The link with this id.
    ///
    /// Ids come from this tree, so they are always in range.
    pub fn link(&self, id: LinkId) -> &Link {
        &self.links[id.0]
    }

    /// The joint with this id.
    pub fn joint(&self, id: JointId) -> &Joint {
        &self.joints[id.0]
    }

    /// The id of the link named `name`.
    pub fn link_id(&self, name: &str) -> Option<LinkId> {
        self.link_index.get(name).copied()
    }

    /// The id of the joint named `name`.
    pub fn joint_id(&self, name: &str) -> Option<JointId> {
        self.joint_index.get(name).copied()
    }

    /// The link named `name`.
    pub fn link_by_name(&self, name: &str) -> Option<&Link> {
        self.link_id(name).map(|id| self.link(id))
    }

    /// The joint named `name`.
    pub fn joint_by_name(&self, name: &str) -> Option<&Joint> {
        self.joint_id(name).map(|id| self.joint(id))
    }

    /// Reads the triangles of every `<mesh>` in the collision geometry through `read`, called once
    /// per distinct file name as written (`package://...`, a path): the model reads no files, so
    /// the caller resolves and parses them (`kinematics-meshes` does both). A file `read` refuses
    /// is an error naming the first link that uses it, the file and the reason.
    pub fn load_meshes(
        &mut self,
        read: &mut dyn FnMut(&str) -> Result<std::sync::Arc<TriangleMesh>, String>,
    ) -> Result<(), MeshLoadError> {
        let mut read_already: BTreeMap<String, std::sync::Arc<TriangleMesh>> = BTreeMap::new();
        for link in &mut self.links {
            for collision in &mut link.collisions {
                if let Shape::Mesh { filename, loaded, .. } = &mut collision.shape {
                    let mesh = match read_already.get(filename.as_str()) {
                        Some(mesh) => mesh.clone(),
                        None => {
                            let mesh = read(filename).map_err(|reason| MeshLoadError {
                                link: link.name.clone(),
                                filename: filename.clone(),
                                reason,
                            })?;
                            read_already.insert(filename.clone(), mesh.clone());
                            mesh
                        }
                    };
                    *loaded = Some(mesh);
                }
            }
        }
        Ok(())
    }

    /// The length of `q`: one entry per independent joint, three for a planar joint, four for a
    /// spherical one, seven for a floating one ([`JointKind::positions`]).
    pub fn dof(&self) -> usize {
        self.dof_joints.len()
    }

    /// The number of velocities: the columns of a Jacobian and the length of `qd` (a floating
    /// joint has six, for its seven entries of `q`, a spherical joint three for its four; every
    /// other joint as many as in `q`).
    pub fn velocity_dof(&self) -> usize {
        self.dof() - self.quaternion_joints().count()
    }

    /// The independent joints, per entry of `q`: `q[i]` drives `dof_joints()[i]` (a planar joint
    /// is listed three times, a spherical one four times, a floating one seven times).
    pub fn dof_joints(&self) -> &[JointId] {
        &self.dof_joints
    }

    /// The name of each entry of `q`: the joint's name, with `.x`, `.y`, `.theta` for a planar
    /// joint's, `.qx`, `.qy`, `.qz`, `.qw` for a spherical one's and `.x`, `.y`, `.z`, `.qx`,
    /// `.qy`, `.qz`, `.qw` for a floating one's ([`JointKind::position_suffixes`]).
    pub fn dof_names(&self) -> Vec<String> {
        self.entry_names(JointKind::position_suffixes)
    }

    /// The name of each velocity (a Jacobian's columns, the entries of `qd`): as
    /// [`KinematicTree::dof_names`], with `.vx, .vy, .vz, .wx, .wy, .wz` for a floating joint and
    /// `.wx, .wy, .wz` for a spherical one.
    pub fn velocity_names(&self) -> Vec<String> {
        self.entry_names(JointKind::velocity_suffixes)
    }

    fn entry_names(&self, suffixes: fn(JointKind) -> &'static [&'static str]) -> Vec<String> {
        let mut names = Vec::with_capacity(self.dof());
        let mut previous = None;
        for &j in &self.dof_joints {
            if previous == Some(j) {
                continue;
            }
            previous = Some(j);
            let joint = self.joint(j);
            match suffixes(joint.kind) {
                [] => names.push(joint.name.clone()),
                list => names.extend(list.iter().map(|s| format!("{}{s}", joint.name))),
            }
        }
        names
    }

    /// Position limits of each entry of `q`, in order (`None` for continuous, planar, spherical
    /// and floating joints).
    pub fn dof_limits(&self) -> Vec<Option<Limits>> {
        self.dof_joints.iter().map(|&j| self.joint(j).limits).collect()
    }

    /// The floating joints, in tree order.
    pub fn floating_joints(&self) -> impl Iterator<Item = JointId> + '_ {
        (0..self.joints.len()).map(JointId).filter(|&j| self.joint(j).kind == JointKind::Floating)
    }

    /// The joints whose entries of `q` hold a quaternion (floating and spherical joints,
    /// [`JointKind::takes_quaternion`]), in tree order. Each is independent (validation refuses a
    /// mimic of one), so each has one fewer velocity than entries of `q`.
    pub fn quaternion_joints(&self) -> impl Iterator<Item = JointId> + '_ {
        (0..self.joints.len()).map(JointId).filter(|&j| self.joint(j).kind.takes_quaternion())
    }

    /// Where each quaternion joint's quaternion starts in `q` (its `qx`; `qy`, `qz`, `qw`
    /// follow), in the order of [`KinematicTree::quaternion_joints`].
    ///
    /// ```
    /// use kinematics_model::parse_source;
    /// let mjcf = r#"<mujoco><worldbody><body name="trunk"><freejoint/>
    ///   <body name="arm"><joint name="shoulder" type="ball"/></body></body></worldbody></mujoco>"#;
    /// let tree = parse_source("r.xml", mjcf)?;
    /// assert_eq!(tree.quaternion_entries(), vec![3, 7]);
    /// assert_eq!((tree.dof(), tree.velocity_dof()), (11, 9));
    /// assert_eq!(tree.dof_names()[7..], ["shoulder.qx", "shoulder.qy", "shoulder.qz", "shoulder.qw"]);
    /// assert_eq!(tree.velocity_names()[6..], ["shoulder.wx", "shoulder.wy", "shoulder.wz"]);
    /// # Ok::<(), kinematics_model::LoadError>(())
    /// ```
    pub fn quaternion_entries(&self) -> Vec<usize> {
        self.quaternion_joints()
            .filter_map(|j| {
                let joint = self.joint(j);
                match (joint.motion, joint.kind.quaternion_offset()) {
                    (JointMotion::Dof(start), Some(offset)) => Some(start + offset),
                    _ => None,
                }
            })
            .collect()
    }

    /// The velocity index of each entry of `q`: the same index shifted down by one for each
    /// quaternion joint (floating or spherical) before it, and `None` for a quaternion joint's own
    /// entries (its velocities start at [`KinematicTree::velocity_start`]).
    pub fn velocity_of_entry(&self) -> Vec<Option<usize>> {
        let mut out = Vec::with_capacity(self.dof());
        let mut shift = 0;
        for (i, &j) in self.dof_joints.iter().enumerate() {
            let joint = self.joint(j);
            if joint.kind.takes_quaternion() {
                out.push(None);
                if matches!(joint.motion, JointMotion::Dof(start) if i + 1 == start + joint.kind.positions()) {
                    shift += 1;
                }
            } else {
                out.push(Some(i - shift));
            }
        }
        out
    }

    /// Where an independent joint's velocities start (`None` for a fixed or mimic joint).
    pub fn velocity_start(&self, joint: JointId) -> Option<usize> {
        let JointMotion::Dof(start) = self.joint(joint).motion else { return None };
        // One fewer velocity than entries for each quaternion joint before: count their first
        // entries.
        let quaternions_before = self.dof_joints[..start]
            .iter()
            .enumerate()
            .filter(|&(i, &j)| {
                let before = self.joint(j);
                before.kind.takes_quaternion() && before.motion == JointMotion::Dof(i)
            })
            .count();
        Some(start - quaternions_before)
    }

    /// The leaves: links below the root with no child joint, in depth-first order (the ends of
    /// the chains; a robot of one link has none).
    ///
    /// ```
    /// let tree = kinematics_model::synthetic::tree(3, 2);
    /// let leaves: Vec<&str> = tree.leaves().map(|l| tree.link(l).name.as_str()).collect();
    /// assert_eq!(leaves.len(), 3, "{leaves:?}");
    /// assert!(tree.leaves().all(|l| tree.link(l).child_joints.is_empty()));
    /// ```
    pub fn leaves(&self) -> impl Iterator<Item = LinkId> + '_ {
        (0..self.links.len())
            .map(LinkId)
            .filter(|&l| self.links[l.0].child_joints.is_empty() && self.links[l.0].parent_joint.is_some())
    }

    /// The number of joints from the root down to `link` (the length of
    /// [`KinematicTree::path_from_root`], without building it).
    pub fn depth(&self, link: LinkId) -> usize {
        self.depth[link.0]
    }

    /// What one joint adds to the robot's [`KinematicTree::reach`]: the lengths of its fixed
    /// translations, plus for a prismatic joint the farthest it slides in the configurations
    /// agreement is checked on (up to 1 beyond finite limits, up to pi + 1 when a side is
    /// unlimited; a mimic joint slides its multiplier times its source's range, plus its offset).
    pub fn joint_reach(&self, id: JointId) -> f64 {
        let joint = self.joint(id);
        let offsets: f64 = joint
            .origin
            .steps()
            .iter()
            .chain(joint.after_motion.steps())
            .map(|s| match s {
                crate::transform::Elementary::Translation(v) => length(*v),
                crate::transform::Elementary::Rotation(..) => 0.0,
            })
            .sum();
        let slide = match (joint.kind, joint.motion) {
            (JointKind::Prismatic, JointMotion::Mimic { source, multiplier, offset, .. }) => {
                multiplier.abs() * stroke(self.joint(source).limits) + offset.abs()
            }
            (JointKind::Prismatic, _) => stroke(joint.limits),
            _ => 0.0,
        };
        offsets + slide
    }

    /// The joints from the root down to `link`, root first.
    pub fn path_from_root(&self, link: LinkId) -> Vec<JointId> {
        let mut path = Vec::with_capacity(self.depth(link));
        let mut at = link;
        while let Some(joint) = self.link(at).parent_joint {
            path.push(joint);
            at = self.joint(joint).parent;
        }
        path.reverse();
        path
    }

    /// The chain from link `base` down to link `tip`.
    ///
    /// Fails when either link is unknown or `base` is not `tip` or one of its ancestors.
    pub fn chain(&self, base: &str, tip: &str) -> Result<Chain, ModelError> {
        let base_id = self.link_id(base).ok_or_else(|| ModelError::NoSuchLink(base.to_owned()))?;
        let tip_id = self.link_id(tip).ok_or_else(|| ModelError::NoSuchLink(tip.to_owned()))?;
        let path = self.path_from_root(tip_id);
        let start = if base_id == self.root() {
            0
        } else {
            match path.iter().position(|&j| self.joint(j).parent == base_id) {
                Some(i) => i,
                None if base_id == tip_id => path.len(),
                None => {
                    return Err(ModelError::NotAChain { base: base.to_owned(), tip: tip.to_owned() });
                }
            }
        };
        Ok(Chain { base: base_id, tip: tip_id, joints: path[start..].to_vec() })
    }

    /// The entries of `q` that move the joints of `chain`, ascending and unique.
    pub fn chain_dofs(&self, chain: &Chain) -> Vec<usize> {
        let mut dofs: Vec<usize> = chain
            .joints
            .iter()
            .filter_map(|&j| match self.joint(j).motion {
                JointMotion::Fixed => None,
                JointMotion::Dof(i) => Some(i..i + self.joint(j).kind.positions()),
                JointMotion::Mimic { dof: i, .. } => Some(i..i + 1),
            })
            .flatten()
            .collect();
        dofs.sort_unstable();
        dofs.dedup();
        dofs
    }
}
