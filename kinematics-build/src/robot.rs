//! The builder: which description, which frames, which name, and where the code goes.
//!
//! `Robot` takes the derive's options as calls, filling the compiler's `Options`; each fault of its
//! rules becomes a `CallFault` naming the call.

use std::path::{Path, PathBuf};

use kinematics_compiler::dynamics::DynamicsRequest;
use kinematics_compiler::emit::Trig;
use kinematics_compiler::options::{
    CollisionOptions, Cover, IkMode, Meshes, OptionFault, OptionKey, Options, floating_base_clash,
};
use kinematics_model::srdf::parse_srdf;
use kinematics_model::{ExactAngles, LoadError, LoadErrorKind, SourceKind};

use crate::emit::{Emit, default_struct_name, emit_source};
use crate::error::{BuildError, CallFault};
use crate::source::{Loaded, load, resolve};
use crate::write::write_atomic;

/// One robot to compile: the options of `#[derive(Kinematics)]` as builder calls.
///
/// | derive key | builder |
/// |---|---|
/// | `urdf = "path"` | [`Robot::urdf`] |
/// | `mjcf = "path"` | [`Robot::mjcf`] |
/// | `dh = "path"` | [`Robot::dh`] |
/// | `base = "link"` | [`Robot::base`] |
/// | `tip = "link"` / `tips(..)` | [`Robot::tip`] (once per tip) / [`Robot::tips`] |
/// | `links = ["a", "b"]` | [`Robot::links`] |
/// | `positions` | [`Robot::positions`] |
/// | `jacobians` | [`Robot::jacobians`] |
/// | `ik` / `ik(free = "joint")` / `ik = "numeric"` | [`Robot::ik`] / [`Robot::ik_free`] / [`Robot::ik_numeric`] |
/// | `floating_base` / `floating_base = "link"` | [`Robot::floating_base`] |
/// | `scalars(f64, f32)` | [`Robot::f32`] |
/// | `crate = "path"` | [`Robot::crate_path`] |
/// | `exact_angles = false` | [`Robot::exact_angles`] |
/// | `trig = "std"` | [`Robot::trig`] |
/// | `collision` / `collision(spheres = 16, sphere_cover = 0.02, meshes = "skip", srdf = "path", packages(NAME = "path"))` | [`Robot::collision`] / [`Robot::spheres`], [`Robot::sphere_cover`], [`Robot::skip_meshes`], [`Robot::srdf`], [`Robot::package`] |
/// | `dynamics` / `dynamics(gravity = [0.0, 0.0, -9.81], inertia_as_written)` | [`Robot::dynamics`] / [`Robot::gravity`], [`Robot::inertia_as_written`] |
///
/// plus [`Robot::struct_name`] (default: the robot's name in UpperCamelCase, see
/// [`default_struct_name`]). Paths are relative to `CARGO_MANIFEST_DIR` (the directory of the
/// `Cargo.toml` whose build script runs), or to [`Robot::manifest_dir`]. The calls fill the
/// compiler's one set of options ([`Options`]), checked by its rules when generating: the faults are
/// [`BuildError::Options`], each naming the call to change.
#[derive(Debug, Clone)]
#[must_use]
pub struct Robot {
    path: PathBuf,
    kind: SourceKind,
    dir: Option<PathBuf>,
    options: Options,
    /// The SRDF file [`Robot::srdf`] names, read when generating.
    srdf: Option<PathBuf>,
    /// The sphere budget and overshoot as given ([`Robot::spheres`], [`Robot::sphere_cover`]).
    cover_given: (Option<usize>, Option<f64>),
    /// Where `package://` meshes are, as given ([`Robot::package`]).
    packages: Vec<(String, PathBuf)>,
    struct_name: Option<String>,
    crate_path: String,
}

impl Robot {
    fn new(path: PathBuf, kind: SourceKind) -> Self {
        Robot {
            path,
            kind,
            dir: None,
            options: Options::default(),
            srdf: None,
            cover_given: (None, None),
            packages: Vec::new(),
            struct_name: None,
            crate_path: "::kinematics".to_owned(),
        }
    }

    /// A URDF file, whatever its extension.
    pub fn urdf(path: impl Into<PathBuf>) -> Self {
        Self::new(path.into(), SourceKind::Urdf)
    }

    /// An MJCF file (MuJoCo's XML), whatever its extension; the files it names (`<include>`,
    /// `<model file>`) are read relative to its directory and embedded in the generated code.
    pub fn mjcf(path: impl Into<PathBuf>) -> Self {
        Self::new(path.into(), SourceKind::Mjcf)
    }

    /// A DH table: JSON if the name ends in `.json`, TOML otherwise.
    pub fn dh(path: impl Into<PathBuf>) -> Self {
        Self::new(path.into(), SourceKind::Dh)
    }

    /// A description whose format the extension names (`.urdf`, `.xml` (URDF or MJCF by its
    /// root element), `.mjcf`, `.toml`, `.json`); any other extension is an error when generating.
    pub fn file(path: impl Into<PathBuf>) -> Self {
        Self::new(path.into(), SourceKind::ByExtension)
    }

    /// Read relative paths from `dir` instead of `CARGO_MANIFEST_DIR` (tools outside cargo).
    pub fn manifest_dir(mut self, dir: impl Into<PathBuf>) -> Self {
        self.dir = Some(dir.into());
        self
    }

    /// The frame every pose is expressed in (default: the root link).
    pub fn base(mut self, link: &str) -> Self {
        self.options.base = Some(link.to_owned());
        self
    }

    /// Adds a tip: one tip gives `tip_pose`, several give `tip_poses` (in the order added).
    pub fn tip(mut self, link: &str) -> Self {
        self.options.tips.push(link.to_owned());
        self
    }

    /// Adds several tips.
    pub fn tips<I, S>(mut self, links: I) -> Self
    where
        I: IntoIterator<Item = S>,
        S: AsRef<str>,
    {
        self.options.tips.extend(links.into_iter().map(|l| l.as_ref().to_owned()));
        self
    }

    /// Only these links in `link_poses` (and `link_positions`, `LINK_NAMES`), in this order,
    /// instead of every link but the base: only their poses are computed. Each name must be a link
    /// of the robot and appear once. Calling it again adds to the list; a list that stays empty is
    /// an error, not every link.
    pub fn links<I, S>(mut self, links: I) -> Self
    where
        I: IntoIterator<Item = S>,
        S: AsRef<str>,
    {
        self.options.links.get_or_insert_with(Vec::new).extend(links.into_iter().map(|l| l.as_ref().to_owned()));
        self
    }

    /// Also generate position-only functions (`tip_position`, `link_positions`).
    pub fn positions(mut self) -> Self {
        self.options.positions = true;
        self
    }

    /// Also generate the tips' velocities: `tip_jacobian` (`LOCAL_WORLD_ALIGNED`),
    /// `tip_jacobian_local`, `tip_pose_and_jacobian`, `tip_twist`, `tip_twist_local` (and with
    /// [`Robot::positions`] `tip_position_jacobian`). Needs a tip.
    pub fn jacobians(mut self) -> Self {
        self.options.jacobians = true;
        self
    }

    /// Also generate the tip's inverse kinematics in closed form (`tip_ik`, `tip_ik_nearest`,
    /// `tip_ik_within_limits`, `IK_FAMILY`) and the numeric solver beside it (`tip_ik_numeric`,
    /// `tip_ik_numeric_with`). Needs exactly one tip whose chain a closed-form family covers
    /// ([`Robot::generate`] says why not otherwise).
    pub fn ik(mut self) -> Self {
        self.options.ik = IkMode::ClosedForm { free: None };
        self
    }

    /// [`Robot::ik`] for a seven-joint arm: `joint`'s value becomes an input of `tip_ik` (and of
    /// `tip_ik_within_limits`; `tip_ik_nearest` takes it from the seed), and the other six are
    /// solved in closed form.
    pub fn ik_free(mut self, joint: &str) -> Self {
        self.options.ik = IkMode::ClosedForm { free: Some(joint.to_owned()) };
        self
    }

    /// Also generate the numeric inverse kinematics of the tip only (`tip_ik_numeric`,
    /// `tip_ik_numeric_with`), for any chain. Needs exactly one tip.
    pub fn ik_numeric(mut self) -> Self {
        self.options.ik = IkMode::Numeric;
        self
    }

    /// A free-flying root: the description's root joined to a new root link `link` (`"world"` for
    /// the derive's bare `floating_base`) by a floating joint `root_joint`, whose seven entries
    /// start `q` (position, then quaternion `qx, qy, qz, qw`), as legged robots are modelled.
    pub fn floating_base(mut self, link: &str) -> Self {
        self.options.floating_base = Some(link.to_owned());
        self
    }

    /// Also generate `f32` functions (`tip_pose_f32`, ...).
    pub fn f32(mut self) -> Self {
        self.options.scalars.f32 = true;
        self
    }

    /// The generated struct's name (a Rust identifier).
    pub fn struct_name(mut self, name: &str) -> Self {
        self.struct_name = Some(name.to_owned());
        self
    }

    /// Where the `kinematics` crate is in the crate that includes the code (default
    /// `::kinematics`), if the dependency was renamed.
    pub fn crate_path(mut self, path: &str) -> Self {
        self.crate_path = path.to_owned();
        self
    }

    /// Which sine and cosine the code calls: ours ([`Trig::Fast`], the default: every angle of a
    /// function in one call, side by side in SIMD lanes) or the platform's ([`Trig::Std`], one call
    /// per angle; the user's crate then needs the `kinematics` crate's `std` feature).
    pub fn trig(mut self, trig: Trig) -> Self {
        self.options.trig = trig;
        self
    }

    /// Whether decimal angles within 1e-8 rad of a multiple of pi/2 are read as that multiple
    /// (`true`, the default; see `kinematics_model::exactness`) or every angle as written
    /// (`false`). The generated `reference()` loads the description with the same policy.
    pub fn exact_angles(mut self, on: bool) -> Self {
        self.options.exact_angles = ExactAngles::on(on);
        self
    }

    /// Also generate collision checking from the links' `<collision>` geometry, covered by
    /// spheres (`sphere_centers`, `SPHERE_RADII`, `SPHERE_LINKS`). Meshes are read (resolved from
    /// the description's folder, [`Robot::package`] first) unless [`Robot::skip_meshes`].
    pub fn collision(mut self) -> Self {
        self.options.collision.get_or_insert_with(CollisionOptions::default);
        self
    }

    /// [`Robot::collision`] with at most `n` spheres per link (with [`Robot::sphere_cover`]
    /// too, whichever is reached first ends a link's cover; neither: at most 10, stopping early
    /// at 1 cm).
    pub fn spheres(mut self, n: usize) -> Self {
        self.cover_given.0 = Some(n);
        self.set_cover()
    }

    /// [`Robot::collision`] with the sphere cover's largest overshoot `metres`: the fewest spheres
    /// the cover finds with no point farther than that beyond the geometry.
    pub fn sphere_cover(mut self, metres: f64) -> Self {
        self.cover_given.1 = Some(metres);
        self.set_cover()
    }

    /// The cover from the budget and overshoot given.
    fn set_cover(mut self) -> Self {
        let (spheres, overshoot) = self.cover_given;
        self.options.collision.get_or_insert_with(CollisionOptions::default).cover = Cover { spheres, overshoot };
        self
    }

    /// Where the meshes of `package://name/...` are: the folder `path` (relative as the
    /// description's is), looked at before `ROS_PACKAGE_PATH`, `AMENT_PREFIX_PATH` and a folder
    /// `name` above the description.
    pub fn package(mut self, name: impl Into<String>, path: impl Into<PathBuf>) -> Self {
        self.packages.push((name.into(), path.into()));
        self
    }

    /// [`Robot::collision`] leaving meshes out (they are read otherwise).
    pub fn skip_meshes(mut self) -> Self {
        self.options.collision.get_or_insert_with(CollisionOptions::default).meshes = Meshes::Skip;
        self
    }

    /// [`Robot::collision`] with MoveIt's semantic description at `path` (relative as the
    /// description's is): its `<disable_collisions>` pairs are left out of `self_collides`. Read
    /// when generating; a link it names that the robot does not have is an error.
    pub fn srdf(mut self, path: impl Into<PathBuf>) -> Self {
        self.options.collision.get_or_insert_with(CollisionOptions::default);
        self.srdf = Some(path.into());
        self
    }

    /// Also generate the dynamics from the links' `<inertial>`s: `gravity_torques(&q)`,
    /// `inverse_dynamics(&q, &qd, &qdd)`, `nonlinear_effects(&q, &qd)`, `mass_matrix(&q)` and
    /// `forward_dynamics(&q, &qd, &tau)` (a `Result`: a mass matrix that is singular at `q` is an
    /// error naming the velocity), each in `f64` (and `f32` with [`Robot::f32`]) and `_generic`
    /// over lanes, and the functions of `q` alone in batches too. Gravity is
    /// `[0.0, 0.0, -9.81]` m/s^2 in the root link's frame unless [`Robot::gravity`] says otherwise.
    ///
    /// [`Robot::generate`] refuses a robot none of whose links has an `<inertial>`, one whose
    /// inertia breaks a rigid body's rules (a negative mass, an entry that is not finite, a tensor
    /// that is not positive semi-definite or, unless [`Robot::inertia_as_written`], breaks the
    /// triangle inequality), naming the link and the line of its `<inertial>`, and an MJCF body
    /// whose mass MuJoCo would infer from its geoms.
    ///
    /// ```
    /// let dir = std::env::temp_dir().join(format!("kinematics-build-dynamics-doc-{}", std::process::id()));
    /// std::fs::create_dir_all(&dir)?;
    /// let urdf = r#"<robot name="pendulum"><link name="base"/>
    ///   <link name="bob"><inertial><origin xyz="0 0 -0.5"/><mass value="2"/>
    ///     <inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>
    ///   <joint name="hinge" type="continuous"><parent link="base"/><child link="bob"/><axis xyz="0 1 0"/></joint>
    /// </robot>"#;
    /// std::fs::write(dir.join("pendulum.urdf"), urdf)?;
    /// let source = kinematics_build::Robot::urdf("pendulum.urdf").manifest_dir(&dir).dynamics().generate()?;
    /// assert!(source.contains("pub fn gravity_torques(q: &[f64; 1]) -> [f64; 1]"));
    /// assert!(source.contains("pub fn mass_matrix(q: &[f64; 1]) -> [[f64; 1]; 1]"));
    /// # std::fs::remove_dir_all(&dir)?;
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn dynamics(mut self) -> Self {
        self.options.dynamics.get_or_insert_with(DynamicsRequest::default);
        self
    }

    /// [`Robot::dynamics`] under the gravity `[x, y, z]` (m/s^2, in the root link's frame; the
    /// default is `[0.0, 0.0, -9.81]`). Each entry must be finite.
    pub fn gravity(mut self, gravity: [f64; 3]) -> Self {
        self.options.dynamics.get_or_insert_with(DynamicsRequest::default).gravity = gravity;
        self
    }

    /// [`Robot::dynamics`] taking inertia tensors whose principal moments break the triangle
    /// inequality as written (real descriptions have them; no rigid body of non-negative density
    /// does). They must still be positive semi-definite.
    pub fn inertia_as_written(mut self) -> Self {
        self.options.dynamics.get_or_insert_with(DynamicsRequest::default).inertia_as_written = true;
        self
    }

    /// [`Robot::dynamics`] with external forces on `links`: also generates
    /// `inverse_dynamics_with_forces` and `forward_dynamics_with_forces`, whose `forces` argument
    /// holds one `[fx, fy, fz, nx, ny, nz]` per link, in this order (the force and its moment about
    /// the link's origin, in the link's own axes), and `FORCE_LINKS`. Each link must be one of the
    /// robot's, named once, with a moving joint between it and the root.
    pub fn forces<S: Into<String>>(mut self, links: impl IntoIterator<Item = S>) -> Self {
        let request = self.options.dynamics.get_or_insert_with(DynamicsRequest::default);
        request.forces.extend(links.into_iter().map(Into::into));
        self
    }

    /// The options the calls so far have set.
    pub fn options(&self) -> &Options {
        &self.options
    }

    /// The description file as the caller wrote it (the name in messages).
    pub fn label(&self) -> String {
        self.path.display().to_string()
    }

    /// The absolute path the description is read from.
    pub fn source_path(&self) -> PathBuf {
        resolve(&self.path, self.dir.as_deref())
    }

    /// The formatted Rust source: a header comment, `pub struct Name;` and its impls.
    ///
    /// Reads and validates the description, checks the options against it (links with "did you
    /// mean", the inverse kinematics' family), compiles and formats. Prints nothing:
    /// [`Robot::write_to_out_dir`] adds cargo's directives.
    pub fn generate(&self) -> Result<String, BuildError> {
        self.generate_reading().map(|(source, _)| source)
    }

    /// [`Robot::generate`], and the mesh files it read.
    fn generate_reading(&self) -> Result<(String, Vec<PathBuf>), BuildError> {
        let mut loaded = self.load()?;
        let mut options = self.options.clone();
        let mut meshes = Vec::new();
        if options.collision.as_ref().is_some_and(|c| c.meshes == Meshes::Read) {
            let mut packages = kinematics_meshes::Packages::new();
            for (name, path) in &self.packages {
                packages.insert(name.clone(), resolve(path, self.dir.as_deref()));
            }
            let resolver = kinematics_meshes::Resolver::new(&self.source_path(), &packages);
            meshes = kinematics_meshes::load_tree_meshes(&mut loaded.tree, &resolver)
                .map_err(|source| BuildError::Mesh { file: self.label(), source })?;
        }
        if let (Some(path), Some(collision)) = (&self.srdf, options.collision.as_mut()) {
            let label = path.display().to_string();
            let text = std::fs::read_to_string(resolve(path, self.dir.as_deref()))
                .map_err(|e| LoadError::new(label.clone(), LoadErrorKind::Io(e)))?;
            let mut srdf = parse_srdf(&text).map_err(|e| LoadError::new(label.clone(), e))?;
            srdf.file = label;
            collision.srdf = Some(srdf);
        }
        let checked = options.check(&loaded.tree).map_err(|rejected| self.faults(rejected.faults))?;
        let name = self.struct_name.clone().unwrap_or_else(|| default_struct_name(loaded.tree.name()));
        let source = emit_source(&Emit { loaded: &loaded, robot: checked, name: &name, crate_path: &self.crate_path })?;
        Ok((source, meshes))
    }

    /// `faults` as the error naming this file and the calls that set the options.
    fn faults(&self, faults: Vec<OptionFault>) -> BuildError {
        let faults = faults.into_iter().map(|fault| CallFault { method: self.method(fault.key), fault }).collect();
        BuildError::Options { file: self.label(), faults }
    }

    /// The call that sets `key`'s option.
    fn method(&self, key: OptionKey) -> &'static str {
        match key {
            OptionKey::Base => ".base(..)",
            OptionKey::Tip(_) => ".tip(..)",
            OptionKey::Link(_) | OptionKey::Links => ".links(..)",
            OptionKey::Positions => ".positions()",
            OptionKey::Jacobians => ".jacobians()",
            OptionKey::Ik => match self.options.ik {
                IkMode::ClosedForm { free: Some(_) } => ".ik_free(..)",
                IkMode::Numeric => ".ik_numeric()",
                _ => ".ik()",
            },
            OptionKey::FloatingBase => ".floating_base(..)",
            OptionKey::Scalars => ".f32()",
            OptionKey::Trig => ".trig(..)",
            OptionKey::ExactAngles => ".exact_angles(..)",
            OptionKey::Collision => ".collision()",
            OptionKey::SphereCover => ".sphere_cover(..)",
            OptionKey::Spheres => ".spheres(..)",
            OptionKey::Srdf => ".srdf(..)",
            OptionKey::Dynamics => ".dynamics()",
            OptionKey::Gravity => ".gravity(..)",
            OptionKey::ForceLink(_) => ".forces(..)",
        }
    }

    /// Reads and validates the description with this builder's format and exactness policy.
    pub(crate) fn load(&self) -> Result<Loaded, BuildError> {
        let (label, path, policy) = (self.label(), self.source_path(), self.options.exact_angles);
        if let Some(link) = &self.options.floating_base {
            // The new root link and joint must be new names.
            let plain = load(&label, path.clone(), self.kind, policy, None)?;
            if let Some(fault) = floating_base_clash(&plain.tree, link) {
                return Err(self.faults(vec![fault]));
            }
        }
        Ok(load(&label, path, self.kind, policy, self.options.floating_base.as_deref())?)
    }

    /// Generates and writes the code to `path` atomically (nothing half-written is left behind on
    /// an error). Prints nothing.
    pub fn write_to(&self, path: impl AsRef<Path>) -> Result<(), BuildError> {
        self.write_reading(path.as_ref()).map(drop)
    }

    /// [`Robot::write_to`], and the mesh files read.
    fn write_reading(&self, path: &Path) -> Result<Vec<PathBuf>, BuildError> {
        let (source, meshes) = self.generate_reading()?;
        write_atomic(path, &source).map_err(|source| BuildError::Write {
            file: self.label(),
            path: path.display().to_string(),
            source,
        })?;
        Ok(meshes)
    }

    /// From a build script: prints `cargo:rerun-if-changed=<description>`, generates, and writes
    /// the code to `$OUT_DIR/<file_name>` atomically. Returns the path written, for `include!`
    /// write `include!(concat!(env!("OUT_DIR"), "/<file_name>"));`.
    pub fn write_to_out_dir(&self, file_name: &str) -> Result<PathBuf, BuildError> {
        println!("cargo:rerun-if-changed={}", self.source_path().display());
        if let Some(srdf) = &self.srdf {
            println!("cargo:rerun-if-changed={}", resolve(srdf, self.dir.as_deref()).display());
        }
        let out = std::env::var_os("OUT_DIR").ok_or(BuildError::NoOutDir)?;
        let path = Path::new(&out).join(file_name);
        for mesh in self.write_reading(&path)? {
            println!("cargo:rerun-if-changed={}", mesh.display());
        }
        Ok(path)
    }
}

#[cfg(test)]
mod tests {
    use super::{Robot, Trig};
    use crate::error::{BuildError, CallFault};
    use kinematics_compiler::options::FaultKind;
    use kinematics_model::LoadErrorKind;

    /// A scratch directory holding `files`, its own on every call: the tests run in parallel,
    /// and two that shared a name (`links`) removed each other's files as they ran.
    fn fixture(test: &str, files: &[(&str, &str)]) -> std::path::PathBuf {
        static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
        let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let dir = std::env::temp_dir().join(format!("kinematics-build-{test}-{}-{call}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        for (name, text) in files {
            std::fs::write(dir.join(name), text).unwrap();
        }
        dir
    }

    const ARM: &str = r#"<robot name="arm">
      <link name="base_link"/> <link name="upper"/> <link name="tool0"/>
      <joint name="shoulder" type="revolute"><parent link="base_link"/><child link="upper"/>
        <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
      <joint name="elbow" type="continuous"><parent link="upper"/><child link="tool0"/>
        <origin xyz="1 0 0"/><axis xyz="0 1 0"/></joint>
    </robot>"#;

    /// The message `robot` fails with, after checking the variant with `is`.
    fn fails(robot: &Robot, is: fn(&BuildError) -> bool) -> String {
        match robot.generate() {
            Ok(_) => panic!("{} should not generate", robot.label()),
            Err(e) => {
                assert!(is(&e), "unexpected variant: {e}");
                e.to_string()
            }
        }
    }

    /// Whether `e` is exactly one option fault, set by `method`, of a kind `is` accepts.
    /// Code as tokens, whatever the lines prettyplease breaks it into: no whitespace, and no final
    /// comma of a signature written over several lines.
    fn bare(text: &str) -> String {
        text.split_whitespace().collect::<String>().replace(",)", ")")
    }

    fn one_fault(e: &BuildError, method: &str, is: fn(&FaultKind) -> bool) -> bool {
        matches!(e, BuildError::Options { faults, .. } if matches!(faults.as_slice(), [CallFault { method: m, fault }] if *m == method && is(&fault.kind)))
    }

    #[test]
    fn a_missing_file_is_named() {
        let dir = fixture("missing", &[]);
        let message = fails(
            &Robot::urdf("robots/none.urdf").manifest_dir(&dir),
            |e| matches!(e, BuildError::Load(l) if matches!(l.kind, LoadErrorKind::Io(_))),
        );
        assert!(message.starts_with("robots/none.urdf: cannot read the file: "), "{message}");
    }

    #[test]
    fn malformed_xml_is_a_syntax_error() {
        let dir = fixture("malformed", &[("bad.urdf", "<robot name=\"x\"><link name=\"a\">")]);
        let message = fails(
            &Robot::urdf("bad.urdf").manifest_dir(&dir),
            |e| matches!(e, BuildError::Load(l) if matches!(l.kind, LoadErrorKind::Syntax { .. })),
        );
        assert!(message.starts_with("bad.urdf: "), "{message}");
    }

    #[test]
    fn a_cycle_is_named() {
        let cycle = r#"<robot name="loop"><link name="root"/><link name="a"/><link name="b"/>
          <joint name="j0" type="fixed"><parent link="root"/><child link="a"/></joint>
          <joint name="j1" type="fixed"><parent link="a"/><child link="b"/></joint>
          <joint name="j2" type="fixed"><parent link="b"/><child link="a"/></joint></robot>"#;
        let dir = fixture("cycle", &[("loop.urdf", cycle)]);
        let message = fails(
            &Robot::urdf("loop.urdf").manifest_dir(&dir),
            |e| matches!(e, BuildError::Load(l) if l.model_errors().is_some()),
        );
        assert!(message.starts_with("loop.urdf: "), "{message}");
        assert!(message.contains("cycle") || message.contains("more than one parent"), "{message}");
    }

    #[test]
    fn every_model_fault_is_listed() {
        let faults = r#"<robot name="faults"><link name="root"/><link name="a"/>
          <joint name="j0" type="revolute"><parent link="root"/><child link="a"/><axis xyz="0 0 0"/>
            <limit lower="1" upper="-1" effort="1" velocity="1"/></joint>
          <joint name="j1" type="fixed"><parent link="a"/><child link="c"/></joint></robot>"#;
        let dir = fixture("faults", &[("faults.urdf", faults)]);
        let message = fails(
            &Robot::urdf("faults.urdf").manifest_dir(&dir),
            |e| matches!(e, BuildError::Load(l) if l.model_errors().is_some_and(|m| m.errors().len() >= 2)),
        );
        assert!(message.contains("joint `j1`: child link `c` does not exist"), "{message}");
        assert!(message.contains("joint `j0`: axis is zero"), "{message}");
    }

    #[test]
    fn trig_chooses_the_sine_and_cosine_the_code_calls() {
        let dir = fixture("trig", &[("arm.urdf", ARM)]);
        let robot = || Robot::urdf("arm.urdf").manifest_dir(&dir).tip("tool0");
        let fast = robot().generate().unwrap();
        let std = robot().trig(Trig::Std).generate().unwrap();
        assert_eq!(fast, robot().trig(Trig::Fast).generate().unwrap());
        assert!(fast.contains("T::sin_cos_many([") && !fast.contains("StdTrig"), "{fast}");
        assert!(std.contains("::kinematics::__private::StdTrig::sin_cos_std(q1)"), "{std}");
        assert!(std.contains("T: ::kinematics::__private::Real + ::kinematics::__private::StdTrig"), "{std}");
        assert!(!std.contains("sin_cos_many"), "{std}");
    }

    /// Every batch of `f32` runs in eight lanes on every CPU but the collision checks' batches
    /// and motions, which take sixteen where the CPU has AVX-512; `f64` in four or eight: the
    /// lane pair each batch, check and motion hands the core (see `ScalarType` in the compiler for
    /// the measurements behind it).
    #[test]
    fn f32_batches_take_eight_lanes_and_the_checks_sixteen_under_avx512() {
        let sphere = r#"<collision><geometry><sphere radius="0.1"/></geometry></collision>"#;
        let arm = ARM
            .replace(r#"<link name="upper"/>"#, &format!(r#"<link name="upper">{sphere}</link>"#))
            .replace(r#"<link name="tool0"/>"#, &format!(r#"<link name="tool0">{sphere}</link>"#));
        let dir = fixture("lanes", &[("arm.urdf", &arm)]);
        let source =
            Robot::urdf("arm.urdf").manifest_dir(&dir).tip("tool0").f32().jacobians().collision().generate().unwrap();
        let code: Vec<&str> = source.lines().map(str::trim).filter(|line| !line.starts_with("///")).collect();
        // Each lane pair, narrow then wide, as the calls name them.
        let pairs = |narrow: &str, wide: &str| {
            code.windows(2)
                .filter(|w| {
                    w[0] == format!("::kinematics::__private::{narrow},")
                        && w[1] == format!("::kinematics::__private::{wide},")
                })
                .count()
        };
        // Per scalar: link poses, tip pose, Jacobians and the sphere centres, each a batch and a
        // column batch, and the shared verdicts over a slice, in eight; collides and
        // self_collides, each a batch and a column batch, and the motions (first collision and
        // yes/no, each one motion and a batch), in sixteen under AVX-512.
        let (eight, sixteen) = (pairs("F32x8", "F32x8"), pairs("F32x8", "F32x16"));
        assert!(eight >= 10, "{eight} f32 lane pairs of eight in {source}");
        assert_eq!(sixteen, 8, "{source}");
        assert_eq!(eight + sixteen, pairs("F64x4", "F64x8"), "{source}");
        assert!(source.contains("in SIMD lanes (`F32x8`, on every CPU)"), "{source}");
        assert!(source.contains("in SIMD lanes (`F32x8`, or `F32x16` where the CPU has AVX-512)"), "{source}");
        assert!(source.contains("in SIMD lanes (`F64x4`, or `F64x8` where the CPU has AVX-512)"), "{source}");
    }

    #[test]
    fn links_choose_what_link_poses_returns() {
        let dir = fixture("links", &[("arm.urdf", ARM)]);
        let robot = || Robot::urdf("arm.urdf").manifest_dir(&dir);
        let listed = robot().links(["tool0", "upper"]).positions().generate().unwrap();
        assert!(listed.contains(r#"pub const LINK_NAMES: [&'static str; 2] = ["tool0", "upper"];"#), "{listed}");
        assert!(listed.contains("-> [[f64; 3]; 2]"), "{listed}");
        // One link is still an array; calls add up.
        let one = robot().links(["tool0"]).generate().unwrap();
        assert!(one.contains("pub fn link_poses(q: &[f64; 2]) -> [::kinematics::__private::Pose<f64>; 1]"), "{one}");
        assert_eq!(
            robot().links(["tool0"]).links(["upper"]).generate().unwrap(),
            robot().links(["tool0", "upper"]).generate().unwrap()
        );
        let message = fails(&robot().links(["upper", "tool9"]), |e| {
            one_fault(
                e,
                ".links(..)",
                |f| matches!(f, FaultKind::UnknownLink(u) if u.role == "listed" && u.link == "tool9" && u.suggestion.as_deref() == Some("tool0")),
            )
        });
        assert_eq!(message, "arm.urdf: `.links(..)`: listed link `tool9` does not exist; did you mean `tool0`?");
        let message = fails(&robot().links(["tool0", "upper", "tool0"]), |e| {
            one_fault(e, ".links(..)", |f| matches!(f, FaultKind::DuplicateLink { link } if link == "tool0"))
        });
        assert_eq!(message, "arm.urdf: `.links(..)`: link `tool0` is listed twice in `links`");
        // An empty list is what the user wrote, and lists nothing: refused, not every link.
        let message = fails(&robot().links(Vec::<String>::new()), |e| {
            one_fault(e, ".links(..)", |f| *f == FaultKind::EmptyLinks)
        });
        assert_eq!(
            message,
            "arm.urdf: `.links(..)`: `links` lists no link: name at least one, or leave the option out for every link"
        );
        // Every fault at once, in the rules' order, each naming its call.
        let message = fails(
            &robot().tip("tool9").links(["upper", "upper"]).jacobians().base("bse"),
            |e| matches!(e, BuildError::Options { faults, .. } if faults.len() == 3),
        );
        assert_eq!(
            message,
            "arm.urdf: `.base(..)`: base link `bse` does not exist; `.tip(..)`: tip link `tool9` \
             does not exist; did you mean `tool0`?; `.links(..)`: link `upper` is listed twice in `links`"
        );
    }

    #[test]
    fn exact_angles_sets_the_policy_of_the_loaded_tree() {
        // A fixed joint turned by pi as ROS spells it (2e-13 rad off).
        let ros_pi = ARM.replace("<origin xyz=\"1 0 0\"/>", "<origin xyz=\"1 0 0\" rpy=\"3.14159265359 0 0\"/>");
        let dir = fixture("exact", &[("arm.urdf", &ros_pi)]);
        let robot = || Robot::urdf("arm.urdf").manifest_dir(&dir);
        let recognised = |r: Robot| r.load().unwrap().tree.recognised_angles().len();
        assert_eq!(recognised(robot()), 1);
        assert_eq!(recognised(robot().exact_angles(true)), 1);
        assert_eq!(recognised(robot().exact_angles(false)), 0);
        assert_eq!(recognised(robot().exact_angles(false).exact_angles(true)), 1);
    }

    #[test]
    fn an_unknown_extension_is_refused() {
        let dir = fixture("extension", &[("arm.xacro", ARM)]);
        let message = fails(
            &Robot::file("arm.xacro").manifest_dir(&dir),
            |e| matches!(e, BuildError::Load(l) if matches!(l.kind, LoadErrorKind::UnknownFormat)),
        );
        assert_eq!(message, "arm.xacro: unknown description format (expected .urdf, .xml, .mjcf, .toml or .json)");
        // Named as URDF explicitly, the same file is fine.
        assert!(Robot::urdf("arm.xacro").manifest_dir(&dir).generate().is_ok());
    }

    #[test]
    fn unknown_links_are_named_with_a_suggestion() {
        let dir = fixture("links", &[("arm.urdf", ARM)]);
        let robot = || Robot::urdf("arm.urdf").manifest_dir(&dir);
        let is = |e: &BuildError| matches!(e, BuildError::Options { .. });
        assert_eq!(
            fails(&robot().tip("tool9"), is),
            "arm.urdf: `.tip(..)`: tip link `tool9` does not exist; did you mean `tool0`?"
        );
        assert_eq!(fails(&robot().base("gripper"), is), "arm.urdf: `.base(..)`: base link `gripper` does not exist");
    }

    #[test]
    fn bad_names_are_refused() {
        let dir = fixture("names", &[("arm.urdf", ARM)]);
        let robot = || Robot::urdf("arm.urdf").manifest_dir(&dir);
        assert_eq!(
            fails(&robot().struct_name("my arm"), |e| matches!(e, BuildError::StructName { .. })),
            "arm.urdf: struct name `my arm` is not a Rust identifier"
        );
        assert_eq!(
            fails(&robot().crate_path("::kin ematics"), |e| matches!(e, BuildError::CratePath { .. })),
            "arm.urdf: crate path `::kin ematics` is not a Rust path"
        );
    }

    #[test]
    fn write_errors_name_the_output_and_leave_nothing() {
        let dir = fixture("write", &[("arm.urdf", ARM)]);
        let robot = Robot::urdf("arm.urdf").manifest_dir(&dir).tip("tool9");
        let out = dir.join("fk.rs");
        assert!(matches!(robot.write_to(&out), Err(BuildError::Options { .. })));
        assert!(!out.exists());
        let missing = dir.join("no").join("fk.rs");
        let e = Robot::urdf("arm.urdf").manifest_dir(&dir).write_to(&missing).unwrap_err();
        assert!(matches!(e, BuildError::Write { .. }), "{e}");
        assert!(e.to_string().starts_with(&format!("arm.urdf: cannot write `{}`: ", missing.display())), "{e}");
        let mut left: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name()).collect();
        left.sort();
        assert_eq!(left, ["arm.urdf"]);
    }

    #[test]
    fn collision_reads_the_srdf_and_refuses_what_it_cannot_check() {
        let spheres = ARM.replace(
            "<link name=\"upper\"/>",
            "<link name=\"upper\"><collision><geometry><sphere radius=\"0.1\"/></geometry></collision></link>",
        );
        let srdf = "<robot name=\"arm\">\n<disable_collisions link1=\"upper\" link2=\"tool9\"/>\n</robot>";
        let dir = fixture("collision", &[("arm.urdf", &spheres), ("arm.srdf", srdf), ("plain.urdf", ARM)]);
        let robot = || Robot::urdf("arm.urdf").manifest_dir(&dir);
        let source = robot().collision().generate().unwrap();
        assert!(source.contains("pub fn sphere_centers(q: &[f64; 2]) -> [[f64; 3]; 1]"), "{source}");
        assert!(source.contains("pub fn collides(") && source.contains("pub fn self_collides("), "{source}");
        let message = fails(&robot().srdf("arm.srdf"), |e| matches!(e, BuildError::Options { .. }));
        assert_eq!(
            message,
            "arm.urdf: `.srdf(..)`: arm.srdf: line 2: <disable_collisions link2=\"tool9\">: link `tool9` does not \
             exist; did you mean `tool0`?"
        );
        let message = fails(&robot().sphere_cover(f64::NAN), |e| matches!(e, BuildError::Options { .. }));
        assert_eq!(
            message,
            "arm.urdf: `.sphere_cover(..)`: `sphere_cover` is NaN (must be a finite positive length in metres)"
        );
        let message = fails(&Robot::urdf("plain.urdf").manifest_dir(&dir).collision(), |e| {
            matches!(e, BuildError::Options { .. })
        });
        assert!(message.contains("no collision geometry"), "{message}");
        let missing = fails(&robot().srdf("none.srdf"), |e| matches!(e, BuildError::Load(_)));
        assert!(missing.starts_with("none.srdf: cannot read the file"), "{missing}");
    }

    /// `.forces(..)` adds the two functions with external forces and `FORCE_LINKS`, implies
    /// `.dynamics()`, and each link it cannot take is a fault naming the call.
    #[test]
    fn forces_write_their_functions_and_name_the_link_at_fault() {
        let ur5 =
            || Robot::urdf("ur5.urdf").manifest_dir(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../robots"));
        let source = bare(&ur5().forces(["tool0", "forearm_link"]).generate().unwrap());
        for signature in [
            "pub const FORCE_LINKS: [&'static str; 2] = [\"tool0\", \"forearm_link\"];",
            "pub fn inverse_dynamics_with_forces(q: &[f64; 6], qd: &[f64; 6], qdd: &[f64; 6], forces: &[[f64; 6]; 2]) -> [f64; 6]",
            "pub fn forward_dynamics_with_forces(q: &[f64; 6], qd: &[f64; 6], tau: &[f64; 6], forces: &[[f64; 6]; 2])",
            "pub fn gravity_torques(q: &[f64; 6]) -> [f64; 6]",
        ] {
            assert!(source.contains(&bare(signature)), "{signature}");
        }
        assert!(!ur5().dynamics().generate().unwrap().contains("with_forces"));
        let message =
            fails(&ur5().forces(["tool9"]), |e| one_fault(e, ".forces(..)", |f| matches!(f, FaultKind::ForceLink(_))));
        assert_eq!(message, "ur5.urdf: `.forces(..)`: force link `tool9` does not exist; did you mean `tool0`?");
    }

    /// `.dynamics()` on the UR5 writes each function of the dynamics in every form, as Rust that
    /// parses; `.gravity(..)` and `.inertia_as_written()` imply it; each fault names its call, the
    /// link and the line of its `<inertial>`.
    #[test]
    fn dynamics_writes_its_functions_and_names_the_inertial_at_fault() {
        let robots = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../robots");
        let ur5 = || Robot::urdf("ur5.urdf").manifest_dir(&robots);
        let source = ur5().dynamics().f32().generate().unwrap();
        syn::parse_file(&source).unwrap_or_else(|e| panic!("the generated file does not parse: {e}\n{source}"));
        for expected in [
            "pub fn gravity_torques(q: &[f64; 6]) -> [f64; 6]",
            "pub fn gravity_torques_f32(q: &[f32; 6]) -> [f32; 6]",
            "pub fn gravity_torques_batch(qs: &[[f64; 6]], out: &mut [[f64; 6]])",
            "pub fn gravity_torques_batch_columns(columns: [&[f64]; 6], out: &mut [[f64; 6]])",
            "pub fn gravity_torques_generic<T: ::kinematics::__private::Real>(q: &[T; 6]) -> [T; 6]",
            "pub fn mass_matrix(q: &[f64; 6]) -> [[f64; 6]; 6]",
            "pub fn mass_matrix_batch_f32(qs: &[[f32; 6]], out: &mut [[[f32; 6]; 6]])",
            "pub fn inverse_dynamics(q: &[f64; 6], qd: &[f64; 6], qdd: &[f64; 6]) -> [f64; 6]",
            "pub fn nonlinear_effects(q: &[f64; 6], qd: &[f64; 6]) -> [f64; 6]",
            "pub fn forward_dynamics(q: &[f64; 6], qd: &[f64; 6], tau: &[f64; 6])",
            "pub fn forward_dynamics_f32(q: &[f32; 6], qd: &[f32; 6], tau: &[f32; 6])",
        ] {
            assert!(bare(&source).contains(&bare(expected)), "missing `{expected}` in\n{source}");
        }
        // Functions of rates take a batch of rows of each argument, and no columns form.
        for expected in [
            "pub fn inverse_dynamics_batch(qs: &[[f64; 6]], qds: &[[f64; 6]], qdds: &[[f64; 6]], out: &mut [[f64; 6]])",
            "pub fn forward_dynamics_batch_f32(qs: &[[f32; 6]], qds: &[[f32; 6]], taus: &[[f32; 6]], out: &mut [[f32; 6]])",
        ] {
            assert!(bare(&source).contains(&bare(expected)), "missing `{expected}`");
        }
        assert!(!source.contains("fn inverse_dynamics_batch_columns"));
        // The default gravity, and another one given: the constants differ, nothing else is asked.
        let default = ur5().dynamics().generate().unwrap();
        assert_eq!(default, ur5().gravity([0.0, 0.0, -9.81]).generate().unwrap());
        assert_eq!(default, ur5().dynamics().dynamics().generate().unwrap());
        assert_ne!(default, ur5().gravity([0.5, 0.0, -9.81]).generate().unwrap());
        assert!(!ur5().generate().unwrap().contains("fn gravity_torques"));

        let inertial = |link: &str, mass: &str, ixx: &str| {
            format!(
                "<link name=\"{link}\">\n<inertial><mass value=\"{mass}\"/>\n<inertia ixx=\"{ixx}\" ixy=\"0\" \
                 ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial></link>"
            )
        };
        let with = |mass: &str, ixx: &str| ARM.replace("<link name=\"upper\"/>", &inertial("upper", mass, ixx));
        let dir = fixture(
            "dynamics",
            &[
                ("negative.urdf", &with("-1", "1")),
                ("triangle.urdf", &with("1", "3")),
                ("nan.urdf", &with("1", "nan")),
                ("plain.urdf", ARM),
            ],
        );
        let robot = |file: &str| Robot::urdf(file).manifest_dir(&dir);
        let is = |e: &BuildError| matches!(e, BuildError::Options { .. });
        assert_eq!(
            fails(&robot("negative.urdf").dynamics(), |e| {
                one_fault(e, ".dynamics()", |f| matches!(f, FaultKind::Dynamics(_)))
            }),
            "negative.urdf: `.dynamics()`: robot `arm`: the <inertial> of link `upper` (line 3): its mass is -1 kg \
             (must be zero or more)"
        );
        let triangle = fails(&robot("triangle.urdf").dynamics(), is);
        assert!(
            triangle.starts_with(
                "triangle.urdf: `.dynamics()`: robot `arm`: the <inertial> of link `upper` (line 3): \
                 its inertia's principal moments [1.0, 1.0, 3.0] kg m^2 break the triangle inequality"
            ),
            "{triangle}"
        );
        // Taken as written, the same tensor compiles.
        let written = robot("triangle.urdf").inertia_as_written().generate().unwrap();
        assert!(written.contains("pub fn mass_matrix("), "{written}");
        let nan = fails(&robot("nan.urdf").dynamics(), is);
        assert!(
            nan.starts_with(
                "nan.urdf: `.dynamics()`: robot `arm`: the <inertial> of link `upper` (line 3): its mass \
                 or inertia is not finite"
            ),
            "{nan}"
        );
        assert_eq!(
            fails(&robot("plain.urdf").dynamics(), |e| one_fault(e, ".dynamics()", |f| *f == FaultKind::NoMass)),
            "plain.urdf: `.dynamics()`: `dynamics` of a robot with no mass: no link has an <inertial> (a link \
             without one is massless)"
        );
        // Every fault at once: the gravity and the link that breaks the triangle inequality.
        let message = fails(&robot("triangle.urdf").gravity([0.0, f64::NAN, -9.81]), |e| {
            matches!(e, BuildError::Options { faults, .. } if matches!(faults.as_slice(), [
                CallFault { method: ".gravity(..)", fault: g },
                CallFault { method: ".dynamics()", fault: d },
            ] if matches!(g.kind, FaultKind::Gravity(_)) && matches!(d.kind, FaultKind::Dynamics(_))))
        });
        assert!(
            message.starts_with(
                "triangle.urdf: `.gravity(..)`: `gravity` is [0.0, NaN, -9.81] (must be three finite numbers, m/s^2 in \
                 the root link's frame); `.dynamics()`: robot `arm`: the <inertial> of link `upper` (line 3)"
            ),
            "{message}"
        );
    }

    /// Up to 128 points (spheres, groups and links), the checks read them computed ahead; beyond,
    /// they place the centres their tests reach from the links' poses (`MAX_POINTS_AHEAD` in the
    /// compiler has the measurements). Both give the same verdicts (the core's tests).
    #[test]
    fn the_checks_compute_their_points_ahead_only_for_few_spheres() {
        let geometry = |shape: &str| {
            ARM.replace(
                "<link name=\"upper\"/>",
                &format!("<link name=\"upper\"><collision><geometry>{shape}</geometry></collision></link>"),
            )
            .replace(
                "<link name=\"tool0\"/>",
                "<link name=\"tool0\"><collision><geometry><sphere radius=\"0.1\"/></geometry></collision></link>",
            )
        };
        let few = geometry("<sphere radius=\"0.1\"/>");
        let many = geometry("<cylinder radius=\"0.1\" length=\"1.0\"/>");
        let dir = fixture("ahead", &[("few.urdf", &few), ("many.urdf", &many)]);
        let few = Robot::urdf("few.urdf").manifest_dir(&dir).collision().generate().unwrap();
        let many = Robot::urdf("many.urdf").manifest_dir(&dir).collision().spheres(200).generate().unwrap();
        let spheres = |source: &str| {
            let line = source.lines().find(|l| l.contains("const SPHERE_RADII: [f64; ")).expect("the radii's constant");
            line.split("[f64; ")
                .nth(1)
                .and_then(|r| r.split(']').next())
                .and_then(|n| n.parse::<usize>().ok())
                .expect("its length")
        };
        assert!(spheres(&few) == 2 && spheres(&many) > 128, "{} and {} spheres", spheres(&few), spheres(&many));
        // The calls as tokens, whatever the lines they are formatted on.
        let (few, many): (String, String) = (few.split_whitespace().collect(), many.split_whitespace().collect());
        assert!(
            few.contains("fngeneric_collision_points") && few.contains("COLLISION_TABLES.collides_points("),
            "{few}"
        );
        assert!(few.contains("COLLISION_TABLES.self_collides_points("), "{few}");
        assert!(!many.contains("generic_collision_points") && many.contains("COLLISION_TABLES.collides("), "{many}");
        assert!(many.contains("COLLISION_TABLES.self_collides("), "{many}");
    }

    #[test]
    fn debug_is_the_message() {
        let dir = fixture("debug", &[("arm.urdf", ARM)]);
        let e = Robot::urdf("arm.urdf").manifest_dir(&dir).tip("tool9").generate().unwrap_err();
        assert_eq!(format!("{e:?}"), e.to_string());
    }

    #[test]
    fn generates_a_struct_with_the_derive_impls() {
        let dir = fixture("generate", &[("arm.urdf", ARM)]);
        let source = Robot::urdf("arm.urdf").manifest_dir(&dir).tip("tool0").positions().f32().generate().unwrap();
        assert!(source.starts_with("// @generated by kinematics-build from `arm.urdf`"), "{source}");
        for expected in [
            "pub struct Arm;",
            "impl Arm {",
            "impl ::kinematics::__private::Kinematics for Arm {",
            "pub fn tip_pose(q: &[f64; 2]) -> ::kinematics::__private::Pose<f64>",
            "pub fn tip_position(q: &[f64; 2]) -> [f64; 3]",
            "pub fn tip_pose_f32(q: &[f32; 2])",
            "pub fn tip_pose_batch(",
            "pub fn tip_pose_batch_f32(",
            "pub fn tip_pose_generic<T: ::kinematics::__private::Real>(",
            "pub fn link_poses(q: &[f64; 2]) -> [::kinematics::__private::Pose<f64>; 2]",
            "::kinematics::__private::parse_source_with(",
        ] {
            assert!(source.contains(expected), "missing `{expected}` in\n{source}");
        }
        // The description is embedded, not included from the generating machine's path.
        assert!(source.contains(ARM) && !source.contains("include_str!"), "{source}");
        // Deterministic, and renamed on request.
        let again = Robot::urdf("arm.urdf").manifest_dir(&dir).tip("tool0").positions().f32().generate().unwrap();
        assert_eq!(source, again);
        let renamed =
            Robot::urdf("arm.urdf").manifest_dir(&dir).struct_name("Two").crate_path("kin").generate().unwrap();
        assert!(
            renamed.contains("pub struct Two;") && renamed.contains("impl kin::__private::Kinematics for Two"),
            "{renamed}"
        );
    }

    #[test]
    fn a_dh_table_named_without_its_extension_is_parsed_as_one() {
        let table = "convention = \"standard\"\nname = \"pendulum\"\n[[joints]]\nname = \"swing\"\na = 1.0\n";
        let dir = fixture("dh", &[("pendulum.table", table)]);
        let source = Robot::dh("pendulum.table").manifest_dir(&dir).generate().unwrap();
        assert!(source.contains("pub struct Pendulum;"), "{source}");
        assert!(source.contains("\"pendulum.table.toml\""), "{source}");
    }

    #[test]
    fn an_mjcf_file_and_the_files_it_includes_are_embedded() {
        let main = r#"<mujoco model="arm"><include file="parts.xml"/>
            <worldbody><body name="link1"><joint name="j"/><site name="tcp" pos="0 0 1"/></body></worldbody></mujoco>"#;
        let parts = r#"<mujoco><default><joint axis="0 1 0" range="-90 90"/></default></mujoco>"#;
        let dir = fixture("mjcf", &[("arm.model", main), ("parts.xml", parts)]);
        let source = Robot::mjcf("arm.model").manifest_dir(&dir).tip("tcp").generate().unwrap();
        // `reference()` reads the main text and the included one from the generated file.
        assert!(source.contains("parse_source_files("), "{source}");
        assert!(source.contains("\"parts.xml\""), "{source}");
        assert!(source.contains(r#"<joint axis="0 1 0" range="-90 90"/>"#), "{source}");
        // By extension a `.model` file is no description; `Robot::file` refuses it.
        assert!(Robot::file("arm.model").manifest_dir(&dir).generate().is_err());
    }
}
