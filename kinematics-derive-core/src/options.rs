//! The `#[kinematics(...)]` attribute, parsed by darling: every key once, each value with its span.
//!
//! ```text
//! #[kinematics(urdf = "robots/ur5.urdf", base = "base", tip = "tool0")]
//! #[kinematics(dh = "robots/ur5.toml", tips("link3", "link6"), positions, scalars(f64, f32))]
//! #[kinematics(urdf = "robots/ur5_ros.urdf", exact_angles = false)]
//! #[kinematics(urdf = "robots/humanoid.urdf", links = ["l_sole", "r_sole"])]
//! #[kinematics(dh(convention = "standard",
//!                 joint(name = "shoulder", a = 1.0),
//!                 joint(name = "elbow", a = 1.0, alpha = "pi/2")))]
//! ```
//!
//! The keys naming the description and the links asked for are defined once, in [`SourceKeys`],
//! and read by both readers of the attribute: [`KinematicsInput`] (every key, the others in
//! [`OutputKeys`]) and [`DescriptionKeys`] (those keys alone, every other skipped).
//!
//! `SourceKeys` are `base`, `tip`, `tips` and `links` with the description's key; `DescriptionKeys`
//! reads the description when another key failed. The keys become the compiler's `Options`, and
//! each `OptionKey` maps back to its key's span; words (`trig`, `ik`) are read through the
//! compiler's `Choice` lists.

use std::collections::BTreeMap;

use darling::ast::NestedMeta;
use darling::util::{Override, PathList, SpannedValue};
use darling::{Error, FromDeriveInput, FromMeta};

use crate::inline_dh::InlineDh;
use kinematics_compiler::dynamics::{DynamicsRequest, STANDARD_GRAVITY};
use kinematics_compiler::options::{
    Choice, CollisionOptions, Cover, IkKind, IkMode, Meshes, OptionKey, Options, Scalars, Trig, choose,
};
use kinematics_model::ExactAngles;

/// The options of one derive.
#[derive(Debug, FromDeriveInput)]
#[darling(attributes(kinematics), supports(struct_any))]
pub struct KinematicsInput {
    /// The struct.
    pub ident: syn::Ident,
    /// Its generics.
    pub generics: syn::Generics,
    /// Every key: those naming the description and links, then (in `rest`) what to emit.
    #[darling(flatten)]
    pub keys: SourceKeys<OutputKeys>,
}

/// The keys naming the description and the links asked for, and `rest`, the other keys as `Rest`
/// reads them. Darling reads `rest`'s keys after these (a flattened field gets the keys its
/// struct does not know), so a fault in one of these is reported before any in `rest`'s keys;
/// among themselves, each group's faults come in the attribute's order.
#[derive(Debug, FromMeta)]
pub struct SourceKeys<Rest> {
    /// `urdf = "path"`.
    #[darling(default)]
    pub urdf: Option<SpannedValue<String>>,
    /// `mjcf = "path"` (MuJoCo's XML).
    #[darling(default)]
    pub mjcf: Option<SpannedValue<String>>,
    /// `dh = "path"` or an inline `dh(...)` table.
    #[darling(default)]
    pub dh: Option<SpannedValue<DhSource>>,
    /// `base = "link"`.
    #[darling(default)]
    pub base: Option<SpannedValue<String>>,
    /// `tip = "link"`.
    #[darling(default)]
    pub tip: Option<SpannedValue<String>>,
    /// `tips("a", "b")`.
    #[darling(default)]
    pub tips: Option<Tips>,
    /// `links = ["a", "b"]`: only these links in `link_poses` (and `link_positions`,
    /// `LINK_NAMES`), in this order.
    #[darling(default)]
    pub links: Option<SpannedValue<Links>>,
    /// `exact_angles = false`: read every decimal angle as written (default `true`: angles within
    /// 1e-8 rad of a multiple of pi/2 are that multiple; see `kinematics_model::exactness`).
    #[darling(default)]
    pub exact_angles: Option<Switch>,
    /// `floating_base` (or `floating_base = "link"`): a free-flying root, the description's root
    /// joined to a new root link (`world` by default) by a floating joint `root_joint`.
    #[darling(default)]
    pub floating_base: Option<SpannedValue<Override<String>>>,
    /// The other keys.
    #[darling(flatten)]
    pub rest: Rest,
}

/// The keys saying what to emit (every key but [`SourceKeys`]'); any other key is an error, with
/// a "did you mean" over both structs' keys.
#[derive(Debug, FromMeta)]
pub struct OutputKeys {
    /// `positions`: also emit position-only functions.
    #[darling(default)]
    pub positions: bool,
    /// `jacobians`: also emit the tips' Jacobians and twists (needs `tip` or `tips`).
    #[darling(default)]
    pub jacobians: darling::util::Flag,
    /// `ik` (or `ik = "closed_form"`): also emit the tip's inverse kinematics in closed form and
    /// the numeric solver beside it (needs `tip`; a chain no family covers is an error naming
    /// why); `ik(free = "joint")`: the same for a seven-joint arm, that joint's value an input;
    /// `ik = "numeric"`: the numeric solver only, for any chain.
    #[darling(default)]
    pub ik: Option<SpannedValue<Override<IkKey>>>,
    /// `scalars(f64, f32)`.
    #[darling(default)]
    pub scalars: Option<ScalarList>,
    /// `trig = "std"`: call the platform's `sin_cos` (one call per angle) instead of ours (the
    /// default, `trig = "fast"`: every angle of a function in one call, side by side in SIMD lanes).
    #[darling(default)]
    pub trig: Option<SpannedValue<Word<Trig>>>,
    /// `collision` (or `collision(spheres = 16, sphere_cover = 0.02, meshes = "skip",
    /// packages(NAME = "path"))`): also emit collision checking's functions from the links'
    /// `<collision>` geometry, covered by spheres.
    #[darling(default)]
    pub collision: Option<SpannedValue<Override<CollisionKey>>>,
    /// `dynamics` (or `dynamics(gravity = [0.0, 0.0, -9.81], inertia_as_written, forces("link"))`):
    /// also emit the dynamics from the links' inertias: gravity torques, inverse dynamics,
    /// nonlinear effects, the mass matrix and forward dynamics, and with `forces` inverse and
    /// forward dynamics with external forces on those links.
    #[darling(default)]
    pub dynamics: Option<Keyed<Override<DynamicsKey>>>,
    /// `crate = "path"` for a renamed dependency.
    #[darling(default, rename = "crate")]
    pub krate: Option<syn::Path>,
}

/// The list form of `collision(...)`.
#[derive(Debug, Clone, FromMeta)]
pub struct CollisionKey {
    /// The sphere budget per link.
    #[darling(default)]
    pub spheres: Option<usize>,
    /// The cover's largest overshoot in metres.
    #[darling(default)]
    pub sphere_cover: Option<f64>,
    /// `meshes = "skip"` (leave meshes out) or `"read"` (the default).
    #[darling(default)]
    pub meshes: Option<Word<Meshes>>,
    /// `packages(NAME = "path", ...)`: where `package://NAME/` meshes are (relative to
    /// `CARGO_MANIFEST_DIR`), looked at before `ROS_PACKAGE_PATH` and the rest.
    #[darling(default)]
    pub packages: Option<SpannedValue<BTreeMap<String, String>>>,
    /// `srdf = "path"`: MoveIt's semantic description, whose `<disable_collisions>` pairs the
    /// self-collision check leaves out (relative to `CARGO_MANIFEST_DIR`).
    #[darling(default)]
    pub srdf: Option<SpannedValue<String>>,
}

/// The list form of `dynamics(...)`.
#[derive(Debug, Clone, FromMeta)]
pub struct DynamicsKey {
    /// `gravity = [x, y, z]` in m/s^2, in the root link's frame (default `[0.0, 0.0, -9.81]`).
    #[darling(default)]
    pub gravity: Option<SpannedValue<Gravity>>,
    /// `inertia_as_written`: take inertia tensors that break the triangle inequality as written
    /// (real descriptions have them); they must still be positive semi-definite.
    #[darling(default)]
    pub inertia_as_written: darling::util::Flag,
    /// `forces("link", ...)`: the links external forces act on, which
    /// `inverse_dynamics_with_forces` and `forward_dynamics_with_forces` take, in this order.
    #[darling(default)]
    pub forces: Option<ForceLinks>,
}

/// `gravity = [x, y, z]`: three numbers in square brackets (integers allowed, signs too).
#[derive(Debug, Clone, Copy)]
pub struct Gravity(pub [f64; 3]);

/// What a malformed `gravity` value is told.
const GRAVITY_SYNTAX: &str = "expected three numbers in square brackets, like `gravity = [0.0, 0.0, -9.81]` (m/s^2)";

impl FromMeta for Gravity {
    fn from_expr(expr: &syn::Expr) -> darling::Result<Self> {
        fn number(expr: &syn::Expr) -> Option<f64> {
            match expr {
                syn::Expr::Lit(syn::ExprLit { lit: syn::Lit::Float(f), .. }) => f.base10_parse().ok(),
                syn::Expr::Lit(syn::ExprLit { lit: syn::Lit::Int(i), .. }) => {
                    i.base10_parse::<i64>().ok().map(|i| i as f64)
                }
                syn::Expr::Unary(syn::ExprUnary { op: syn::UnOp::Neg(_), expr, .. }) => number(expr).map(|x| -x),
                syn::Expr::Group(group) => number(&group.expr),
                _ => None,
            }
        }
        let syn::Expr::Array(array) = expr else {
            if let syn::Expr::Group(group) = expr {
                return Self::from_expr(&group.expr);
            }
            return Err(Error::custom(GRAVITY_SYNTAX).with_span(expr));
        };
        let values: Vec<f64> = array.elems.iter().filter_map(number).collect();
        match <[f64; 3]>::try_from(values) {
            Ok(gravity) if array.elems.len() == 3 => Ok(Gravity(gravity)),
            _ => Err(Error::custom(GRAVITY_SYNTAX).with_span(expr)),
        }
    }
}

impl OutputKeys {
    /// The `gravity` given in `dynamics(...)`, if any.
    pub fn gravity(&self) -> Option<&SpannedValue<Gravity>> {
        match &self.dynamics.as_ref()?.value {
            Override::Explicit(key) => key.gravity.as_ref(),
            Override::Inherit => None,
        }
    }

    /// The links of `forces(...)` given in `dynamics(...)` (none when not given).
    pub fn force_links(&self) -> &[SpannedValue<String>] {
        match self.dynamics.as_ref().map(|key| &key.value) {
            Some(Override::Explicit(DynamicsKey { forces: Some(ForceLinks(links)), .. })) => links,
            _ => &[],
        }
    }

    /// The `packages(...)` given in `collision(...)`, if any.
    pub fn packages(&self) -> Option<&SpannedValue<BTreeMap<String, String>>> {
        match self.collision.as_ref()?.as_ref() {
            Override::Explicit(key) => key.packages.as_ref(),
            Override::Inherit => None,
        }
    }

    /// The `srdf` path given in `collision(...)`, if any.
    pub fn srdf(&self) -> Option<&SpannedValue<String>> {
        match self.collision.as_ref()?.as_ref() {
            Override::Explicit(key) => key.srdf.as_ref(),
            Override::Inherit => None,
        }
    }
}

/// Every key beyond [`SourceKeys`]', skipped (for [`DescriptionKeys`]).
#[derive(Debug)]
pub struct SkippedKeys;

impl FromMeta for SkippedKeys {
    fn from_list(_: &[NestedMeta]) -> darling::Result<Self> {
        Ok(SkippedKeys)
    }
}

/// The value of the `ik` key beyond the bare word: `ik = "numeric"` (a kind) or
/// `ik(free = "joint")`.
#[derive(Debug, Clone)]
pub enum IkKey {
    /// `ik = "..."`.
    Kind(IkKind),
    /// `ik(free = "joint")`.
    Free(String),
}

/// A key whose value is one of a few words ([`Choice`]: `trig = "std"`): read by the compiler's
/// one list of the words, an unknown word refused with the choices and a "did you mean".
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Word<C>(pub C);

impl<C: Choice> FromMeta for Word<C> {
    fn from_value(value: &syn::Lit) -> darling::Result<Self> {
        match value {
            syn::Lit::Str(word) => choose(&word.value()).map(Word).map_err(|e| Error::custom(e).with_span(word)),
            other => Err(Error::custom(format!(
                "expected a word in quotes, like `{} = \"{}\"`",
                C::KEY.name(),
                C::CHOICES[0].0
            ))
            .with_span(other)),
        }
    }
}

/// The list form of `ik(...)`.
#[derive(Debug, FromMeta)]
struct IkList {
    free: String,
}

impl FromMeta for IkKey {
    fn from_value(value: &syn::Lit) -> darling::Result<Self> {
        Word::<IkKind>::from_value(value).map(|Word(kind)| IkKey::Kind(kind))
    }

    fn from_list(items: &[NestedMeta]) -> darling::Result<Self> {
        Ok(IkKey::Free(IkList::from_list(items)?.free))
    }
}

/// The new root link's name for `floating_base` (`world` unless named).
fn floating_base(key: Option<&SpannedValue<Override<String>>>) -> Option<SpannedValue<String>> {
    key.map(|k| {
        let name = match k.as_ref() {
            Override::Inherit => "world".to_owned(),
            Override::Explicit(name) => name.clone(),
        };
        SpannedValue::new(name, k.span())
    })
}

/// What the crate-private `source::read` needs: the keys that name the description, its
/// exactness policy and its free-flying root.
#[derive(Debug)]
pub struct SourceOptions<'a> {
    /// The struct (errors with no key of their own are spanned on it).
    pub ident: &'a syn::Ident,
    /// `urdf = "path"`.
    pub urdf: Option<&'a SpannedValue<String>>,
    /// `mjcf = "path"`.
    pub mjcf: Option<&'a SpannedValue<String>>,
    /// `dh = ...`.
    pub dh: Option<&'a SpannedValue<DhSource>>,
    /// `exact_angles`.
    pub exact_angles: ExactAngles,
    /// `floating_base`: the new root link's name, spanned on the key.
    pub floating_base: Option<SpannedValue<String>>,
}

/// The keys of [`SourceKeys`] read on their own with every other key skipped. When a key darling
/// cannot read fails the whole attribute, the description is still read with these, so its faults
/// are reported beside that key's instead of after it is fixed.
#[derive(Debug, FromDeriveInput)]
#[darling(attributes(kinematics), supports(struct_any))]
pub struct DescriptionKeys {
    ident: syn::Ident,
    #[darling(flatten)]
    keys: SourceKeys<SkippedKeys>,
}

impl DescriptionKeys {
    /// The options the description's keys set.
    pub fn options(&self) -> Options {
        self.keys.options()
    }

    /// Where the option `key` is written (the struct's name where these keys do not say).
    pub fn span_of(&self, key: OptionKey) -> proc_macro2::Span {
        self.keys.span_of(key).unwrap_or_else(|| self.ident.span())
    }

    /// Whether a description is named at all (a misspelt `urdf` or `dh` is the other key's fault,
    /// not a second one to report).
    pub fn names_a_description(&self) -> bool {
        self.keys.urdf.is_some() || self.keys.mjcf.is_some() || self.keys.dh.is_some()
    }

    /// What loading needs.
    pub fn source(&self) -> SourceOptions<'_> {
        self.keys.source(&self.ident)
    }
}

impl<Rest> SourceKeys<Rest> {
    /// The tip links, from `tip` then the entries of `tips`.
    pub fn tips(&self) -> Vec<SpannedValue<String>> {
        let mut all: Vec<SpannedValue<String>> = self.tip.iter().cloned().collect();
        if let Some(list) = &self.tips {
            all.extend(list.0.iter().cloned());
        }
        all
    }

    /// The entries of `links`, in order (empty when the key is absent: every link).
    pub fn links(&self) -> Vec<SpannedValue<String>> {
        self.links.as_ref().map(|l| l.as_ref().0.clone()).unwrap_or_default()
    }

    /// The exactness policy: `exact_angles = true` (the default) or `false`.
    pub fn exact_angles(&self) -> ExactAngles {
        match self.exact_angles {
            Some(Switch(on)) => ExactAngles::on(on),
            None => ExactAngles::default(),
        }
    }

    /// The options these keys set (every other option at its default).
    pub fn options(&self) -> Options {
        Options {
            base: self.base.as_ref().map(|b| b.as_ref().clone()),
            tips: self.tips().into_iter().map(|t| t.as_ref().clone()).collect(),
            links: self.links.as_ref().map(|l| l.as_ref().0.iter().map(|l| l.as_ref().clone()).collect()),
            floating_base: floating_base(self.floating_base.as_ref()).map(|f| f.as_ref().clone()),
            exact_angles: self.exact_angles(),
            ..Options::default()
        }
    }

    /// Where one of these keys' options is written, if it is one of them and written: a link's
    /// own name for a listed link or a tip.
    pub fn span_of(&self, key: OptionKey) -> Option<proc_macro2::Span> {
        match key {
            OptionKey::Base => self.base.as_ref().map(SpannedValue::span),
            OptionKey::Tip(i) => self.tips().get(i).map(SpannedValue::span),
            OptionKey::Link(i) => self.links().get(i).map(SpannedValue::span),
            OptionKey::Links => self.links.as_ref().map(SpannedValue::span),
            OptionKey::FloatingBase => self.floating_base.as_ref().map(SpannedValue::span),
            _ => None,
        }
    }

    /// What loading needs, `ident` being the struct's name.
    pub fn source<'a>(&'a self, ident: &'a syn::Ident) -> SourceOptions<'a> {
        SourceOptions {
            ident,
            urdf: self.urdf.as_ref(),
            mjcf: self.mjcf.as_ref(),
            dh: self.dh.as_ref(),
            exact_angles: self.exact_angles(),
            floating_base: floating_base(self.floating_base.as_ref()),
        }
    }
}

impl KinematicsInput {
    /// The tip links, from `tip` or `tips`.
    pub fn tips(&self) -> Vec<SpannedValue<String>> {
        self.keys.tips()
    }

    /// What loading needs.
    pub fn source(&self) -> SourceOptions<'_> {
        self.keys.source(&self.ident)
    }

    /// The keys saying what to emit.
    pub fn output(&self) -> &OutputKeys {
        &self.keys.rest
    }
}

impl OutputKeys {
    /// The sine and cosine asked for (ours by default).
    pub fn trig(&self) -> Trig {
        self.trig.as_ref().map_or_else(Trig::default, |t| t.as_ref().0)
    }

    /// The inverse kinematics asked for.
    pub fn ik_mode(&self) -> IkMode {
        let Some(key) = &self.ik else { return IkMode::Off };
        match key.as_ref() {
            Override::Inherit | Override::Explicit(IkKey::Kind(IkKind::ClosedForm)) => {
                IkMode::ClosedForm { free: None }
            }
            Override::Explicit(IkKey::Free(joint)) => IkMode::ClosedForm { free: Some(joint.clone()) },
            Override::Explicit(IkKey::Kind(IkKind::Numeric)) => IkMode::Numeric,
        }
    }

    /// The scalar types asked for (`f64` by default), an entry that is neither into `errors`
    /// (none at all is the compiler's rule's).
    pub fn scalars(&self, errors: &mut darling::error::Accumulator) -> Scalars {
        let Some(list) = &self.scalars else { return Scalars::default() };
        let mut scalars = Scalars { f64: false, f32: false };
        for path in &list.paths {
            match path.get_ident().map(ToString::to_string).as_deref() {
                Some("f64") => scalars.f64 = true,
                Some("f32") => scalars.f32 = true,
                _ => errors.push(Error::custom("expected `f64` or `f32`").with_span(path)),
            }
        }
        scalars
    }
}

impl KinematicsInput {
    /// The compiler's options these keys set, an entry of `scalars` that names no scalar type
    /// into `errors` (the rules between options are the compiler's, [`Options::check`]).
    pub fn options(&self, errors: &mut darling::error::Accumulator) -> Options {
        let output = &self.keys.rest;
        Options {
            positions: output.positions,
            jacobians: output.jacobians.is_present(),
            ik: output.ik_mode(),
            scalars: output.scalars(errors),
            trig: output.trig(),
            collision: output.collision.as_ref().map(|key| match key.as_ref() {
                Override::Inherit => CollisionOptions::default(),
                Override::Explicit(key) => CollisionOptions {
                    cover: match (key.spheres, key.sphere_cover) {
                        (None, None) => Cover::default(),
                        (spheres, overshoot) => Cover { spheres, overshoot },
                    },
                    meshes: key.meshes.map_or_else(Meshes::default, |Word(m)| m),
                    srdf: None,
                },
            }),
            dynamics: output.dynamics.as_ref().map(|key| match &key.value {
                Override::Inherit => DynamicsRequest::default(),
                Override::Explicit(key) => DynamicsRequest {
                    gravity: key.gravity.as_ref().map_or(STANDARD_GRAVITY, |g| g.as_ref().0),
                    inertia_as_written: key.inertia_as_written.is_present(),
                    forces: output.force_links().iter().map(|link| link.as_ref().clone()).collect(),
                },
            }),
            ..self.keys.options()
        }
    }

    /// Where the option `key` is written: its key's span (a link's own name for a listed link or
    /// a tip), or the struct's name for an option without one.
    pub fn span_of(&self, key: OptionKey) -> proc_macro2::Span {
        let output = &self.keys.rest;
        let span = match key {
            OptionKey::Jacobians => output.jacobians.is_present().then(|| output.jacobians.span()),
            OptionKey::Ik => output.ik.as_ref().map(SpannedValue::span),
            OptionKey::Scalars => output.scalars.as_ref().map(|list| list.span),
            OptionKey::Trig => output.trig.as_ref().map(SpannedValue::span),
            // The span darling keeps of `collision(...)` is its first entry's (`sphere_cover`
            // when it is given: the cover's fault is spanned there).
            OptionKey::Collision | OptionKey::SphereCover | OptionKey::Spheres => {
                output.collision.as_ref().map(SpannedValue::span)
            }
            // The path's own span, else (the fault found without it) the `collision` key's.
            OptionKey::Srdf => {
                output.srdf().map(SpannedValue::span).or_else(|| output.collision.as_ref().map(SpannedValue::span))
            }
            // The key's own name, whatever its list holds: an inertia's fault is no entry's.
            OptionKey::Dynamics => output.dynamics.as_ref().map(|key| key.span),
            // The vector's own span, else the `dynamics` key's.
            OptionKey::Gravity => {
                output.gravity().map(SpannedValue::span).or_else(|| output.dynamics.as_ref().map(|key| key.span))
            }
            // The link's own string, else the `dynamics` key's.
            OptionKey::ForceLink(i) => output
                .force_links()
                .get(i)
                .map(SpannedValue::span)
                .or_else(|| output.dynamics.as_ref().map(|key| key.span)),
            // A bare word has no span of its own.
            OptionKey::Positions => None,
            source => self.keys.span_of(source),
        };
        span.unwrap_or_else(|| self.ident.span())
    }
}

/// A key's value and the span of the key's own name: darling's `SpannedValue` of a list
/// (`dynamics(inertia_as_written)`) spans its first entry, which a fault of the whole key would
/// point at.
#[derive(Debug, Clone)]
pub struct Keyed<T> {
    /// The value.
    pub value: T,
    /// The key's name.
    pub span: proc_macro2::Span,
}

impl<T: FromMeta> FromMeta for Keyed<T> {
    fn from_meta(item: &syn::Meta) -> darling::Result<Self> {
        // A word or a list, never `key = value` (darling would say only "Unexpected type `bool`").
        if let syn::Meta::NameValue(pair) = item {
            let key = pair.path.get_ident().map_or_else(|| "the key".to_owned(), |i| format!("`{i}`"));
            let message = format!("{key} takes no value: write it alone, or with its settings in parentheses");
            return Err(Error::custom(message).with_span(&pair.value));
        }
        let value = T::from_meta(item).map_err(|e| e.with_span(item))?;
        Ok(Keyed { value, span: syn::spanned::Spanned::span(item.path()) })
    }
}

/// `scalars(f64, f32)`: the paths listed, and where the key is (darling's span of a list is the
/// macro's call site, so an empty list's fault would point at the derive).
#[derive(Debug, Clone)]
pub struct ScalarList {
    /// The entries.
    pub paths: Vec<syn::Path>,
    /// The key's own span.
    pub span: proc_macro2::Span,
}

impl FromMeta for ScalarList {
    fn from_meta(item: &syn::Meta) -> darling::Result<Self> {
        let paths = PathList::from_meta(item)?;
        Ok(ScalarList { paths: paths.to_vec(), span: syn::spanned::Spanned::span(item.path()) })
    }
}

/// `tips("a", "b")`: string literals, each with its span.
#[derive(Debug, Clone)]
pub struct Tips(pub Vec<SpannedValue<String>>);

impl FromMeta for Tips {
    fn from_list(items: &[NestedMeta]) -> darling::Result<Self> {
        quoted_links(items, "tips(\"left_hand\", \"right_hand\")").map(Tips)
    }
}

/// `forces("a", "b")` in `dynamics(...)`: the links external forces act on, string literals each
/// with its span.
#[derive(Debug, Clone)]
pub struct ForceLinks(pub Vec<SpannedValue<String>>);

/// What a `forces` that is no list is told.
const FORCES_SYNTAX: &str = "expected link names in quotes in parentheses, like `forces(\"tool0\", \"wrist_3_link\")`";

impl FromMeta for ForceLinks {
    fn from_list(items: &[NestedMeta]) -> darling::Result<Self> {
        quoted_links(items, "forces(\"tool0\", \"wrist_3_link\")").map(ForceLinks)
    }

    fn from_word() -> darling::Result<Self> {
        Err(Error::custom(FORCES_SYNTAX))
    }

    fn from_expr(expr: &syn::Expr) -> darling::Result<Self> {
        Err(Error::custom(FORCES_SYNTAX).with_span(expr))
    }
}

/// The string literals of a list, each with its span; anything else is an error showing `example`.
fn quoted_links(items: &[NestedMeta], example: &str) -> darling::Result<Vec<SpannedValue<String>>> {
    let mut errors = Error::accumulator();
    let mut links = Vec::new();
    for item in items {
        match item {
            NestedMeta::Lit(syn::Lit::Str(s)) => links.push(SpannedValue::new(s.value(), s.span())),
            other => {
                errors.push(Error::custom(format!("expected a link name in quotes, like `{example}`")).with_span(other))
            }
        }
    }
    errors.finish_with(links)
}

/// `links = ["a", "b"]`: string literals in an array, each with its span (an empty list is read,
/// and refused by the compiler's rule).
#[derive(Debug, Clone)]
pub struct Links(pub Vec<SpannedValue<String>>);

impl FromMeta for Links {
    fn from_expr(expr: &syn::Expr) -> darling::Result<Self> {
        let syn::Expr::Array(array) = expr else {
            if let syn::Expr::Group(group) = expr {
                // The invisible group a `macro_rules!` wraps a fragment in.
                return Self::from_expr(&group.expr);
            }
            return Err(Error::custom(LINKS_SYNTAX).with_span(expr));
        };
        let mut errors = Error::accumulator();
        let mut links = Vec::new();
        for element in &array.elems {
            match element {
                syn::Expr::Lit(syn::ExprLit { lit: syn::Lit::Str(s), .. }) => {
                    links.push(SpannedValue::new(s.value(), s.span()));
                }
                other => errors.push(Error::custom(LINKS_SYNTAX).with_span(other)),
            }
        }
        errors.finish_with(Links(links))
    }
}

/// What a malformed `links` value is told.
const LINKS_SYNTAX: &str = "expected link names in quotes in square brackets, like `links = [\"l_sole\", \"r_sole\"]`";

/// Where a DH table comes from.
#[derive(Debug, Clone)]
pub enum DhSource {
    /// A TOML or JSON file.
    File(String),
    /// A table written in the attribute.
    Inline(Box<InlineDh>),
}

impl FromMeta for DhSource {
    fn from_string(value: &str) -> darling::Result<Self> {
        Ok(DhSource::File(value.to_owned()))
    }

    fn from_list(items: &[NestedMeta]) -> darling::Result<Self> {
        InlineDh::from_list(items).map(|t| DhSource::Inline(Box::new(t)))
    }
}

/// A key that is on or off: `key = true`, `key = false`, or the bare `key` (on).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Switch(pub bool);

impl FromMeta for Switch {
    fn from_word() -> darling::Result<Self> {
        Ok(Switch(true))
    }

    fn from_value(value: &syn::Lit) -> darling::Result<Self> {
        match value {
            syn::Lit::Bool(b) => Ok(Switch(b.value)),
            other => Err(Error::custom("expected `true` or `false`").with_span(other)),
        }
    }

    fn from_expr(expr: &syn::Expr) -> darling::Result<Self> {
        match expr {
            syn::Expr::Lit(lit) => Self::from_value(&lit.lit),
            syn::Expr::Group(group) => Self::from_expr(&group.expr),
            other => Err(Error::custom("expected `true` or `false`").with_span(other)),
        }
    }
}
