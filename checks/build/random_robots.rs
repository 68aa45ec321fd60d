//! A fixed-seed set of random robots, as description text: the shapes generated code must get
//! right (one link, zero degrees of freedom, prismatic joints, mimic chains, runs of fixed joints,
//! deep chains, wide trees, skewed axes, quarter turns written exactly and as ROS decimals, DH
//! tables in both conventions), each with the options it is compiled with (base, tips, positions,
//! scalars, exactness policy).
//!
//! Shared by the build script (which compiles every robot through `emit_robot`) and the tests
//! (which generate the set again and compare it byte for byte with what was compiled). Pure: no
//! IO, no clock, no hash map; the only randomness is [`SplitMix64`] from a fixed seed.
//!
//! The set runs from one link to deep chains of about 40 joints.

use std::fmt::Write as _;

/// One generated robot and the options it is compiled with.
#[derive(Debug, Clone, PartialEq)]
pub struct RandomRobot {
    /// Identifier stem, unique in the set (`random_07_mimic_chain`).
    pub name: String,
    /// File name as the description's label (`random_07_mimic_chain.urdf`).
    pub file: String,
    /// The description text.
    pub text: String,
    /// The shape it was drawn as.
    pub shape: &'static str,
    /// The link poses are expressed in (`None`: the root).
    pub base: Option<String>,
    /// Tip links (may be empty).
    pub tips: Vec<String>,
    /// Position-only functions too.
    pub positions: bool,
    /// `f64` typed functions.
    pub f64: bool,
    /// `f32` typed functions.
    pub f32: bool,
    /// The exactness policy: decimal quarter turns recognised (the default) or not.
    pub exact_angles: bool,
}

/// splitmix64 (Steele, Lea and Flood): a small generator whose stream depends on the seed alone.
pub struct SplitMix64(u64);

impl SplitMix64 {
    pub fn new(seed: u64) -> Self {
        SplitMix64(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `0..n` (`n > 0`).
    pub fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n as u64) as usize
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    pub fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }

    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}

/// A number as description text: shortest round-trip form, or rounded to a few decimals (as
/// people write them).
fn num(rng: &mut SplitMix64, x: f64) -> String {
    let text = match rng.below(3) {
        0 => format!("{x:?}"),
        1 => format!("{x:.4}"),
        _ => format!("{x:.2}"),
    };
    // `-0.00` is a valid number, but keep the text plain.
    if text.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') { "0.0".to_owned() } else { text }
}

/// Angles as URDF writes them: exact quarter turns as `f64` literals (`1.5707963267948966`), as
/// ROS decimals (`3.14159265359`, `1.57079632679`), near misses that must stay numbers (`1.5708`),
/// zero, and arbitrary values.
const QUARTER_TURN_TEXTS: [&str; 14] = [
    "1.5707963267948966",
    "-1.5707963267948966",
    "3.141592653589793",
    "-3.141592653589793",
    "3.14159265359",
    "-3.14159265359",
    "1.57079632679",
    "-1.57079632679",
    "4.71238898038",
    "6.28318530718",
    "1.570796327",
    "1.5708",
    "-3.1416",
    "0.7853981633974483",
];

fn angle(rng: &mut SplitMix64, quarter_turns: f64) -> String {
    if rng.chance(quarter_turns) {
        return (*rng.pick(&QUARTER_TURN_TEXTS)).to_owned();
    }
    match rng.below(3) {
        0 => "0".to_owned(),
        _ => {
            let x = rng.range(-3.2, 3.2);
            num(rng, x)
        }
    }
}

fn length(rng: &mut SplitMix64) -> String {
    match rng.below(4) {
        0 => "0.0".to_owned(),
        _ => {
            let x = rng.range(-0.8, 0.8);
            num(rng, x)
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    Revolute,
    Continuous,
    Prismatic,
    Fixed,
    Planar,
    Floating,
}

impl Kind {
    fn urdf(self) -> &'static str {
        match self {
            Kind::Revolute => "revolute",
            Kind::Continuous => "continuous",
            Kind::Prismatic => "prismatic",
            Kind::Fixed => "fixed",
            Kind::Planar => "planar",
            Kind::Floating => "floating",
        }
    }

    /// Whether the joint takes several values of `q` (no mimic follows or is one).
    fn several(self) -> bool {
        matches!(self, Kind::Planar | Kind::Floating)
    }
}

/// One joint of a URDF tree: the child is link `index + 1`.
#[derive(Debug, Clone)]
struct Joint {
    parent: usize,
    kind: Kind,
    xyz: [String; 3],
    rpy: [String; 3],
    axis: [String; 3],
    /// (joint followed, multiplier, offset)
    mimic: Option<(usize, String, String)>,
}

/// What a tree's joints look like.
#[derive(Debug, Clone, Copy)]
struct Style {
    /// Weights of revolute, continuous, prismatic, fixed.
    kinds: [usize; 4],
    /// Chance that an rpy angle is a quarter-turn text.
    quarter_turns: f64,
    /// Chance that an axis is skewed (general direction, not necessarily unit length).
    skewed: f64,
    /// Chance that a moving joint mimics an earlier moving joint.
    mimic: f64,
}

const PLAIN: Style = Style { kinds: [4, 2, 1, 1], quarter_turns: 0.3, skewed: 0.2, mimic: 0.1 };

fn kind(rng: &mut SplitMix64, weights: [usize; 4]) -> Kind {
    let total: usize = weights.iter().sum();
    let mut r = rng.below(total);
    for (k, w) in [Kind::Revolute, Kind::Continuous, Kind::Prismatic, Kind::Fixed].into_iter().zip(weights) {
        if r < w {
            return k;
        }
        r -= w;
    }
    Kind::Fixed
}

fn axis(rng: &mut SplitMix64, skewed: f64) -> [String; 3] {
    if rng.chance(skewed) {
        // General directions, some far from unit length (the model normalises).
        let scale = *rng.pick(&[1.0, 1.0, 0.5, 3.0]);
        let mut v = [0.0; 3];
        for x in &mut v {
            *x = rng.range(-1.0, 1.0);
        }
        let norm = v.iter().map(|x| x * x).sum::<f64>().sqrt().max(0.1);
        return v.map(|x| format!("{:?}", x / norm * scale));
    }
    let axes = ["1 0 0", "0 1 0", "0 0 1", "-1 0 0", "0 -1 0", "0 0 -1"];
    let mut parts = rng.pick(&axes).split(' ').map(str::to_owned);
    [(); 3].map(|()| parts.next().unwrap_or_default())
}

fn joint(rng: &mut SplitMix64, parent: usize, kind: Kind, style: &Style) -> Joint {
    Joint {
        parent,
        kind,
        xyz: [length(rng), length(rng), length(rng)],
        rpy: [angle(rng, style.quarter_turns), angle(rng, style.quarter_turns), angle(rng, style.quarter_turns)],
        axis: axis(rng, style.skewed),
        mimic: None,
    }
}

/// Multipliers and offsets of mimic joints: negative, fractional, whole, with and without offsets.
fn mimic_terms(rng: &mut SplitMix64) -> (String, String) {
    let multiplier = match rng.below(4) {
        0 => (*rng.pick(&["-1", "2", "0.5", "-0.25", "1"])).to_owned(),
        _ => {
            let x = rng.range(-2.0, 2.0);
            num(rng, x)
        }
    };
    let offset = match rng.below(3) {
        0 => "0".to_owned(),
        _ => {
            let x = rng.range(-1.0, 1.0);
            num(rng, x)
        }
    };
    (multiplier, offset)
}

/// Lets some moving joints mimic an earlier moving joint (possibly a mimic joint itself).
fn add_mimics(rng: &mut SplitMix64, joints: &mut [Joint], chance: f64) {
    for k in 0..joints.len() {
        if joints[k].kind == Kind::Fixed || !rng.chance(chance) {
            continue;
        }
        let earlier: Vec<usize> = (0..k).filter(|&i| joints[i].kind != Kind::Fixed).collect();
        if earlier.is_empty() {
            continue;
        }
        let source = *rng.pick(&earlier);
        let (m, o) = mimic_terms(rng);
        joints[k].mimic = Some((source, m, o));
    }
}

/// A tree in which joint `k` hangs from `parents[k]` (a link index below `k + 1`).
fn tree_with_parents(rng: &mut SplitMix64, parents: &[usize], style: &Style) -> Vec<Joint> {
    let mut joints: Vec<Joint> = parents
        .iter()
        .map(|&p| {
            let k = kind(rng, style.kinds);
            joint(rng, p, k, style)
        })
        .collect();
    add_mimics(rng, &mut joints, style.mimic);
    joints
}

fn chain_parents(n: usize) -> Vec<usize> {
    (0..n).collect()
}

fn random_parents(rng: &mut SplitMix64, n: usize) -> Vec<usize> {
    (0..n).map(|k| rng.below(k + 1)).collect()
}

fn urdf_text(name: &str, joints: &[Joint]) -> String {
    let mut text = format!("<?xml version=\"1.0\"?>\n<robot name=\"{name}\">\n  <link name=\"l0\"/>\n");
    for k in 0..joints.len() {
        let _ = writeln!(text, "  <link name=\"l{}\"/>", k + 1);
    }
    for (k, j) in joints.iter().enumerate() {
        let _ = writeln!(text, "  <joint name=\"j{k}\" type=\"{}\">", j.kind.urdf());
        let _ = writeln!(text, "    <parent link=\"l{}\"/>\n    <child link=\"l{}\"/>", j.parent, k + 1);
        let _ = writeln!(text, "    <origin xyz=\"{}\" rpy=\"{}\"/>", j.xyz.join(" "), j.rpy.join(" "));
        if j.kind != Kind::Fixed {
            let _ = writeln!(text, "    <axis xyz=\"{}\"/>", j.axis.join(" "));
        }
        match j.kind {
            Kind::Revolute => {
                let _ = writeln!(text, "    <limit lower=\"-2.5\" upper=\"1.75\" effort=\"10\" velocity=\"2\"/>");
            }
            Kind::Prismatic => {
                let _ = writeln!(text, "    <limit lower=\"-0.3\" upper=\"0.6\" effort=\"10\" velocity=\"2\"/>");
            }
            Kind::Continuous | Kind::Fixed | Kind::Planar | Kind::Floating => {}
        }
        if let Some((source, m, o)) = &j.mimic {
            let _ = writeln!(text, "    <mimic joint=\"j{source}\" multiplier=\"{m}\" offset=\"{o}\"/>");
        }
        let _ = writeln!(text, "  </joint>");
    }
    text + "</robot>\n"
}

/// Links with no children (leaves) of a tree given by its joints.
fn leaves(joints: &[Joint]) -> Vec<usize> {
    (1..=joints.len()).filter(|&l| !joints.iter().any(|j| j.parent == l)).collect()
}

/// How a generated robot is compiled: base, tips, outputs, scalars, policy.
struct Options {
    base: Option<String>,
    tips: Vec<String>,
    positions: bool,
    f64: bool,
    f32: bool,
    exact_angles: bool,
}

/// Options drawn at random for a robot with `links` link names (the first is the root) and
/// `leaves` (indices into `links`).
fn options(rng: &mut SplitMix64, links: &[String], leaves: &[usize]) -> Options {
    let n = links.len();
    let base_index = if n > 1 && rng.chance(0.3) { rng.below(n) } else { 0 };
    let base = (base_index != 0).then(|| links[base_index].clone());
    let candidates: Vec<usize> = (0..n).filter(|&i| i != base_index).collect();
    let mut tips: Vec<usize> = Vec::new();
    if !candidates.is_empty() {
        match rng.below(6) {
            0 => {} // no tips
            1 | 2 => tips.push(*rng.pick(&candidates)),
            3 => tips.extend(leaves.iter().copied().filter(|&l| l != base_index)),
            _ => {
                for _ in 0..(2 + rng.below(3)) {
                    let t = *rng.pick(&candidates);
                    if !tips.contains(&t) {
                        tips.push(t);
                    }
                }
            }
        }
    }
    let (f64, f32) = match rng.below(8) {
        0 => (true, false),
        1 => (false, true),
        _ => (true, true),
    };
    Options {
        base,
        tips: tips.into_iter().map(|t| links[t].clone()).collect(),
        positions: rng.below(4) != 0,
        f64,
        f32,
        exact_angles: true,
    }
}

/// The URDF robots' link names.
fn urdf_links(joints: &[Joint]) -> Vec<String> {
    (0..=joints.len()).map(|l| format!("l{l}")).collect()
}

/// A DH row as generated: TOML key-value pairs in order.
fn dh_row(rng: &mut SplitMix64, i: usize, degrees: bool) -> Vec<(&'static str, String)> {
    let exact = ["\"0\"", "\"pi/2\"", "\"-pi/2\"", "\"pi\"", "\"-pi\"", "\"pi/4\"", "\"3*pi/2\""];
    let decimal = ["3.14159265359", "1.57079632679", "-1.57079632679", "1.5708", "1.5707963267948966"];
    let a = |rng: &mut SplitMix64| -> String {
        match rng.below(5) {
            0 | 1 => (*rng.pick(&exact)).to_owned(),
            2 if !degrees => (*rng.pick(&decimal)).to_owned(),
            2 => (*rng.pick(&["90.0", "-90.0", "180.0", "45.0", "0.0"])).to_owned(),
            _ if degrees => format!("{:.1}", rng.range(-180.0, 180.0)),
            _ => {
                let x = rng.range(-3.2, 3.2);
                num(rng, x)
            }
        }
    };
    let prismatic = rng.chance(0.2);
    let mut row = vec![("name", format!("\"q{}\"", i + 1))];
    if rng.chance(0.3) {
        row.push(("link", format!("\"frame_{}\"", i + 1)));
    }
    if prismatic {
        row.push(("type", "\"prismatic\"".to_owned()));
    }
    row.push(("a", length(rng)));
    row.push(("alpha", a(rng)));
    row.push(("d", length(rng)));
    if rng.chance(0.4) {
        row.push(("theta", a(rng)));
    }
    if rng.chance(0.4) {
        row.push(("offset", if prismatic { length(rng) } else { a(rng) }));
    }
    if rng.chance(0.6) {
        let (lo, hi) = if prismatic {
            ("-0.25", "0.5")
        } else if degrees {
            ("-170.0", "150.0")
        } else {
            (*rng.pick(&["\"-pi\"", "-2.9"]), *rng.pick(&["\"pi/2\"", "2.7"]))
        };
        row.push(("lower", lo.to_owned()));
        row.push(("upper", hi.to_owned()));
    }
    row
}

/// A DH table (TOML or JSON text) and its link names (base first).
fn dh_table(
    rng: &mut SplitMix64,
    name: &str,
    rows: usize,
    modified: bool,
    json: bool,
    tool: Option<bool>,
) -> (String, Vec<String>) {
    let degrees = rng.chance(0.25);
    let mut table: Vec<(&str, String)> = vec![
        ("name", format!("\"{name}\"")),
        ("convention", if modified { "\"modified\"" } else { "\"standard\"" }.to_owned()),
        ("angle_unit", if degrees { "\"degrees\"" } else { "\"radians\"" }.to_owned()),
        ("base_link", "\"base\"".to_owned()),
    ];
    let mut links = vec!["base".to_owned()];
    let rows: Vec<Vec<(&str, String)>> = (0..rows).map(|i| dh_row(rng, i, degrees)).collect();
    for (i, row) in rows.iter().enumerate() {
        let link = row.iter().find(|(k, _)| *k == "link").map(|(_, v)| v.trim_matches('"').to_owned());
        links.push(link.unwrap_or_else(|| format!("link{}", i + 1)));
    }
    let fixed = |rng: &mut SplitMix64, name: &str| -> Vec<(&'static str, String)> {
        let xyz = format!("[{}, {}, {}]", len_number(rng), len_number(rng), len_number(rng));
        let rpy_value = |rng: &mut SplitMix64| match rng.below(3) {
            0 => "\"pi/2\"".to_owned(),
            1 => "0.0".to_owned(),
            _ if degrees => "30.0".to_owned(),
            _ => "0.3".to_owned(),
        };
        let rpy = format!("[{}, {}, {}]", rpy_value(rng), rpy_value(rng), rpy_value(rng));
        vec![("name", format!("\"{name}\"")), ("xyz", xyz), ("rpy", rpy)]
    };
    let base = rng.chance(0.4).then(|| fixed(rng, "base_frame"));
    let tool = tool.unwrap_or_else(|| rng.chance(0.5)).then(|| fixed(rng, "tool"));
    if tool.is_some() {
        links.push("tool".to_owned());
    }
    let text = if json {
        let object = |pairs: &[(&str, String)]| {
            let fields: Vec<String> = pairs.iter().map(|(k, v)| format!("\"{k}\": {v}")).collect();
            format!("{{{}}}", fields.join(", "))
        };
        for (key, section) in [("base", &base), ("tool", &tool)] {
            if let Some(section) = section {
                table.push((key, object(section)));
            }
        }
        let rows: Vec<String> = rows.iter().map(|r| format!("    {}", object(r))).collect();
        table.push(("joints", format!("[\n{}\n  ]", rows.join(",\n"))));
        let fields: Vec<String> = table.iter().map(|(k, v)| format!("  \"{k}\": {v}")).collect();
        format!("{{\n{}\n}}\n", fields.join(",\n"))
    } else {
        let mut text = String::new();
        for (k, v) in &table {
            let _ = writeln!(text, "{k} = {v}");
        }
        for (key, section) in [("base", &base), ("tool", &tool)] {
            if let Some(section) = section {
                let _ = writeln!(text, "\n[{key}]");
                for (k, v) in section {
                    // The base has no name of its own.
                    if !(key == "base" && *k == "name") {
                        let _ = writeln!(text, "{k} = {v}");
                    }
                }
            }
        }
        for row in &rows {
            let _ = writeln!(text, "\n[[joints]]");
            for (k, v) in row {
                let _ = writeln!(text, "{k} = {v}");
            }
        }
        text
    };
    (text, links)
}

fn len_number(rng: &mut SplitMix64) -> String {
    let x = rng.range(-0.5, 0.5);
    format!("{x:.3}")
}

/// The fixed-seed set: about sixty robots, every shape several times.
pub fn generate() -> Vec<RandomRobot> {
    let mut rng = SplitMix64::new(0x006b_696e_655f_3133);
    let mut robots = Vec::new();
    let mut push = |rng: &mut SplitMix64,
                    shape: &'static str,
                    text: String,
                    ext: &str,
                    links: Vec<String>,
                    leaves: Vec<usize>,
                    tweak: &dyn Fn(&mut Options)| {
        let mut o = options(rng, &links, &leaves);
        tweak(&mut o);
        let name = format!("random_{:02}_{shape}", robots.len());
        robots.push(RandomRobot {
            file: format!("{name}.{ext}"),
            name,
            text,
            shape,
            base: o.base,
            tips: o.tips,
            positions: o.positions,
            f64: o.f64,
            f32: o.f32,
            exact_angles: o.exact_angles,
        });
    };
    let mut urdf = |rng: &mut SplitMix64, shape: &'static str, joints: Vec<Joint>, tweak: &dyn Fn(&mut Options)| {
        let text = urdf_text(shape, &joints);
        push(rng, shape, text, "urdf", urdf_links(&joints), leaves(&joints), tweak);
    };
    let keep = |_: &mut Options| {};
    let root_base = |o: &mut Options| o.base = None;

    // One link, no joints: nothing to compute but the constants.
    urdf(&mut rng, "single_link", Vec::new(), &keep);
    // Exactly one joint, of each kind; once seen from the child.
    for k in [Kind::Revolute, Kind::Prismatic, Kind::Continuous, Kind::Fixed] {
        let j = vec![joint(&mut rng, 0, k, &PLAIN)];
        urdf(&mut rng, "one_joint", j, &root_base);
    }
    let j = vec![joint(&mut rng, 0, Kind::Revolute, &PLAIN)];
    urdf(&mut rng, "one_joint", j, &|o: &mut Options| o.base = Some("l1".to_owned()));
    // Zero degrees of freedom: only fixed joints, as a chain and as trees.
    let fixed_only = Style { kinds: [0, 0, 0, 1], ..PLAIN };
    for n in [2, 5, 7] {
        let parents = if n == 5 { chain_parents(n) } else { random_parents(&mut rng, n) };
        let j = tree_with_parents(&mut rng, &parents, &fixed_only);
        urdf(&mut rng, "fixed_only", j, &keep);
    }
    // Prismatic joints, mostly.
    let prismatic = Style { kinds: [1, 0, 4, 1], ..PLAIN };
    for n in [3, 6, 9] {
        let parents = if n == 9 { random_parents(&mut rng, n) } else { chain_parents(n) };
        let j = tree_with_parents(&mut rng, &parents, &prismatic);
        urdf(&mut rng, "prismatic", j, &keep);
    }
    // Mimic chains: a mimic of a mimic of a mimic, negative and fractional multipliers, offsets.
    for n in [4, 6, 8, 10, 12] {
        let style = Style { kinds: [3, 2, 1, 0], mimic: 0.6, ..PLAIN };
        let parents = if n % 4 == 0 { random_parents(&mut rng, n) } else { chain_parents(n) };
        let mut j = tree_with_parents(&mut rng, &parents, &style);
        // Force a chain of three mimics: j1 follows j0, j2 follows j1, j3 follows j2.
        for k in 1..4 {
            if j[k].kind == Kind::Fixed {
                j[k].kind = Kind::Revolute;
            }
            if j[0].kind == Kind::Fixed {
                j[0].kind = Kind::Continuous;
            }
            let (m, o) = mimic_terms(&mut rng);
            j[k].mimic = Some((k - 1, m, o));
        }
        urdf(&mut rng, "mimic_chain", j, &keep);
    }
    // Runs of fixed joints between moving ones.
    for _ in 0..4 {
        let mut joints = Vec::new();
        let moving = Style { kinds: [3, 1, 1, 0], ..PLAIN };
        while joints.len() < 14 {
            let parent = joints.len();
            let k = kind(&mut rng, moving.kinds);
            joints.push(joint(&mut rng, parent, k, &moving));
            for _ in 0..(2 + rng.below(4)) {
                let parent = joints.len();
                joints.push(joint(&mut rng, parent, Kind::Fixed, &moving));
            }
        }
        add_mimics(&mut rng, &mut joints, 0.1);
        urdf(&mut rng, "fixed_runs", joints, &keep);
    }
    // Deep chains (~40 joints).
    for style in [PLAIN, Style { kinds: [1, 1, 0, 0], quarter_turns: 0.5, skewed: 0.0, mimic: 0.0 }] {
        let j = tree_with_parents(&mut rng, &chain_parents(40), &style);
        urdf(&mut rng, "deep_chain", j, &keep);
    }
    // Wide trees: a root with 8 or more children, some with short chains below.
    for width in [8, 9, 12] {
        let mut parents: Vec<usize> = vec![0; width];
        for k in width..(width + rng.below(6) + 2) {
            parents.push(1 + rng.below(k));
        }
        let j = tree_with_parents(&mut rng, &parents, &PLAIN);
        urdf(&mut rng, "wide_tree", j, &keep);
    }
    // Skewed axes everywhere.
    for n in [3, 5, 8] {
        let style = Style { skewed: 0.9, ..PLAIN };
        let parents = if n == 8 { random_parents(&mut rng, n) } else { chain_parents(n) };
        let j = tree_with_parents(&mut rng, &parents, &style);
        urdf(&mut rng, "skewed_axes", j, &keep);
    }
    // Quarter turns, exact and as decimals; with the policy on (the default) and off.
    for (n, exact_angles) in [(6, true), (10, true), (8, true), (6, false), (10, false), (7, false)] {
        let style = Style { quarter_turns: 0.9, skewed: 0.0, ..PLAIN };
        let parents = if n == 8 || n == 7 { random_parents(&mut rng, n) } else { chain_parents(n) };
        let j = tree_with_parents(&mut rng, &parents, &style);
        urdf(&mut rng, if exact_angles { "quarter_turns" } else { "quarter_turns_literal" }, j, &|o: &mut Options| {
            o.exact_angles = exact_angles;
        });
    }
    // Random trees of every kind.
    for n in [2, 3, 4, 5, 6, 7, 9, 11, 13, 16] {
        let parents = random_parents(&mut rng, n);
        let j = tree_with_parents(&mut rng, &parents, &PLAIN);
        urdf(&mut rng, "random_tree", j, &keep);
    }
    // DH tables: both conventions, TOML and JSON, one row to a deep chain.
    let mut dh = |rng: &mut SplitMix64,
                  shape: &'static str,
                  rows: usize,
                  modified: bool,
                  json: bool,
                  tweak: &dyn Fn(&mut Options)| {
        // A one-row table with and without a tool frame; others with one at random.
        let tool = (rows == 1).then_some(json);
        let (text, links) = dh_table(rng, shape, rows, modified, json, tool);
        let leaf = links.len() - 1;
        push(rng, shape, text, if json { "json" } else { "toml" }, links, vec![leaf], tweak);
    };
    for modified in [false, true] {
        let shape = if modified { "dh_modified" } else { "dh_standard" };
        dh(&mut rng, shape, 1, modified, false, &root_base);
        dh(&mut rng, shape, 1, modified, true, &root_base);
        for (rows, json) in [(2, false), (3, true), (5, false), (6, false), (7, true), (24, false)] {
            dh(&mut rng, shape, rows, modified, json, &keep);
        }
    }
    let off = |o: &mut Options| o.exact_angles = false;
    dh(&mut rng, "dh_standard_literal", 6, false, false, &off);
    dh(&mut rng, "dh_modified_literal", 6, true, false, &off);
    // Floating and planar joints (drawn last, so the robots above stay as they were): a free-flying
    // root under random trees, a floating joint mid-chain, planar joints with skewed normals.
    // (shape, joints, which joints become which kind, a chain rather than a random tree)
    type Several = (&'static str, usize, &'static [(usize, Kind)], bool);
    let shapes: [Several; 7] = [
        ("floating_root", 6, &[(0, Kind::Floating)], false),
        ("floating_root", 9, &[(0, Kind::Floating)], false),
        ("floating_root", 4, &[(0, Kind::Floating)], true),
        ("floating_mid", 7, &[(3, Kind::Floating)], true),
        ("planar", 5, &[(0, Kind::Planar)], true),
        ("planar", 8, &[(1, Kind::Planar), (4, Kind::Planar)], false),
        ("planar_and_floating", 9, &[(0, Kind::Floating), (2, Kind::Planar)], false),
    ];
    for (shape, n, at, chain) in shapes {
        let parents = if chain { chain_parents(n) } else { random_parents(&mut rng, n) };
        let mut j = tree_with_parents(&mut rng, &parents, &Style { mimic: 0.3, skewed: 0.4, ..PLAIN });
        for &(k, kind) in at {
            j[k].kind = kind;
        }
        // A mimic follows one value with one value.
        for k in 0..j.len() {
            let follows_several = j[k].mimic.as_ref().is_some_and(|(source, ..)| j[*source].kind.several());
            if j[k].kind.several() || follows_several {
                j[k].mimic = None;
            }
        }
        let text = urdf_text(shape, &j);
        push(&mut rng, shape, text, "urdf", urdf_links(&j), leaves(&j), &keep);
    }
    robots
}
