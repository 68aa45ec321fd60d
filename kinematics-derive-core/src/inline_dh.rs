//! A DH table written in the attribute, as in a textbook: the convention, then one row per joint.
//!
//! ```text
//! dh(convention = "standard",
//!    joint(name = "shoulder_pan", d = 0.089159, alpha = "pi/2"),
//!    joint(name = "shoulder_lift", a = -0.425),
//!    joint(name = "slide", type = "prismatic", offset = 0.1, lower = 0.0, upper = 0.5))
//! ```
//!
//! Keys and meanings are those of a DH file (see `kinematics_model::dh`); numbers may be negative,
//! angles may be exact strings such as `"pi/2"`.
//!
//! The positional form is the table itself, one `row` per joint, columns `a, alpha, d, theta`
//! (then optionally `lower, upper`); a first column `"prismatic"` makes the joint prismatic:
//!
//! ```text
//! dh(convention = "standard",
//!    //   joint             a        alpha    d         theta
//!    row("shoulder_pan",    0.0,    "pi/2",  0.089159, 0.0),
//!    row("shoulder_lift",  -0.425,   0.0,    0.0,      0.0, "-pi", "pi"),
//!    row("lift", "prismatic", 0.0,   0.0,    0.1,      0.0, 0.0, 0.5))
//! ```
//!
//! Prefer it when the table has more than one row: clippy's `duplicated_attributes` lint takes
//! the repeated keys of keyword rows (`a = ...` in every `joint(...)`) for duplicates.

use darling::ast::NestedMeta;
use darling::{Error, FromMeta};
use kinematics_model::dh::{AngleUnit, DhConvention, DhFixed, DhJointType, DhRow, DhTable, Value};

/// A number, negative numbers included, or an exact angle string.
#[derive(Debug, Clone, PartialEq)]
pub struct Number(pub Value);

impl FromMeta for Number {
    fn from_value(lit: &syn::Lit) -> darling::Result<Self> {
        match lit {
            syn::Lit::Float(f) => f.base10_parse::<f64>().map(|x| Number(Value::Number(x))).map_err(Error::from),
            syn::Lit::Int(i) => i.base10_parse::<f64>().map(|x| Number(Value::Number(x))).map_err(Error::from),
            syn::Lit::Str(s) => Ok(Number(Value::Text(s.value()))),
            _ => Err(Error::unexpected_lit_type(lit)),
        }
        .map_err(|e| e.with_span(lit))
    }

    fn from_expr(expr: &syn::Expr) -> darling::Result<Self> {
        match expr {
            syn::Expr::Lit(lit) => Self::from_value(&lit.lit),
            syn::Expr::Group(group) => Self::from_expr(&group.expr),
            syn::Expr::Unary(syn::ExprUnary { op: syn::UnOp::Neg(_), expr: inner, .. }) => {
                match Self::from_expr(inner)? {
                    Number(Value::Number(x)) => Ok(Number(Value::Number(-x))),
                    Number(Value::Text(t)) => Ok(Number(Value::Text(format!("-{t}")))),
                }
            }
            _ => Err(Error::unexpected_expr_type(expr).with_span(expr)),
        }
    }
}

fn number(n: &Option<Number>) -> f64 {
    match n {
        Some(Number(Value::Number(x))) => *x,
        _ => 0.0,
    }
}

/// One row.
#[derive(Debug, Clone, FromMeta)]
pub struct InlineRow {
    name: String,
    #[darling(default)]
    link: Option<String>,
    #[darling(default, rename = "type")]
    kind: Option<String>,
    #[darling(default)]
    a: Option<Number>,
    #[darling(default)]
    alpha: Option<Number>,
    #[darling(default)]
    d: Option<Number>,
    #[darling(default)]
    theta: Option<Number>,
    #[darling(default)]
    offset: Option<Number>,
    #[darling(default)]
    lower: Option<Number>,
    #[darling(default)]
    upper: Option<Number>,
    #[darling(default)]
    velocity: Option<f64>,
    #[darling(default)]
    effort: Option<f64>,
}

/// One positional row: `row("name", ["prismatic",] a, alpha, d, theta[, lower, upper])`.
#[derive(Debug, Clone)]
pub struct PositionalRow(InlineRow);

impl FromMeta for PositionalRow {
    fn from_list(items: &[NestedMeta]) -> darling::Result<Self> {
        let usage = "expected `row(\"name\", a, alpha, d, theta)`, optionally with `\"prismatic\"` after the name and `lower, upper` at the end";
        let mut values = Vec::new();
        for item in items {
            match item {
                NestedMeta::Lit(lit) => values.push(Number::from_value(lit)?),
                other => return Err(Error::custom(usage).with_span(other)),
            }
        }
        let Some(Number(Value::Text(name))) = values.first().cloned() else {
            return Err(Error::custom(usage));
        };
        let mut rest = values[1..].to_vec();
        let mut kind = None;
        if let Some(Number(Value::Text(t))) = rest.first()
            && (t == "prismatic" || t == "revolute")
        {
            kind = Some(t.clone());
            rest.remove(0);
        }
        if rest.len() != 4 && rest.len() != 6 {
            return Err(Error::custom(format!("{usage}; found {} numbers", rest.len())));
        }
        let mut columns = rest.into_iter().map(Some);
        let mut next = || columns.next().flatten();
        Ok(PositionalRow(InlineRow {
            name,
            link: None,
            kind,
            a: next(),
            alpha: next(),
            d: next(),
            theta: next(),
            offset: None,
            lower: next(),
            upper: next(),
            velocity: None,
            effort: None,
        }))
    }
}

/// The base or tool transform: `tool(name = "flange", xyz(0, 0, 0.107), rpy(0, 0, "pi"))`.
#[derive(Debug, Clone, FromMeta)]
pub struct InlineFixed {
    #[darling(default)]
    name: Option<String>,
    #[darling(default)]
    xyz: Option<Triple>,
    #[darling(default)]
    rpy: Option<Triple>,
}

/// Three numbers: `xyz(0, 0, 0.107)`.
#[derive(Debug, Clone)]
pub struct Triple([Value; 3]);

impl FromMeta for Triple {
    fn from_list(items: &[NestedMeta]) -> darling::Result<Self> {
        let values: Vec<Value> = items
            .iter()
            .map(|item| match item {
                NestedMeta::Lit(lit) => Number::from_value(lit).map(|n| n.0),
                other => Err(Error::custom("expected a number").with_span(other)),
            })
            .collect::<darling::Result<_>>()?;
        match <[Value; 3]>::try_from(values) {
            Ok(v) => Ok(Triple(v)),
            Err(v) => Err(Error::custom(format!("expected 3 numbers, found {}", v.len()))),
        }
    }
}

/// A whole inline table.
#[derive(Debug, Clone, FromMeta)]
pub struct InlineDh {
    convention: String,
    #[darling(default)]
    name: Option<String>,
    #[darling(default)]
    angle_unit: Option<String>,
    #[darling(default)]
    base_link: Option<String>,
    #[darling(default)]
    base: Option<InlineFixed>,
    #[darling(default)]
    tool: Option<InlineFixed>,
    #[darling(multiple, rename = "joint")]
    joints: Vec<InlineRow>,
    #[darling(multiple, rename = "row")]
    rows: Vec<PositionalRow>,
}

impl InlineDh {
    /// The table in the model's terms (the same structure a DH file deserialises into).
    pub fn to_table(&self) -> darling::Result<DhTable> {
        let mut errors = Error::accumulator();
        let convention = match self.convention.as_str() {
            "standard" | "distal" => DhConvention::Standard,
            "modified" | "craig" | "proximal" => DhConvention::Modified,
            other => {
                errors.push(Error::unknown_value_with_alts(other, ["standard", "modified"].iter()).at("convention"));
                DhConvention::Standard
            }
        };
        let angle_unit = match self.angle_unit.as_deref() {
            None | Some("radians") => AngleUnit::Radians,
            Some("degrees") => AngleUnit::Degrees,
            Some(other) => {
                errors.push(Error::unknown_value_with_alts(other, ["radians", "degrees"].iter()).at("angle_unit"));
                AngleUnit::Radians
            }
        };
        if !self.joints.is_empty() && !self.rows.is_empty() {
            errors.push(Error::custom(
                "write the table with `row(...)` or with `joint(...)`, not both: their order would be lost",
            ));
        }
        let rows: Vec<&InlineRow> = self.joints.iter().chain(self.rows.iter().map(|r| &r.0)).collect();
        let joints = rows
            .into_iter()
            .enumerate()
            .map(|(i, row)| {
                let kind = match row.kind.as_deref() {
                    None | Some("revolute") => DhJointType::Revolute,
                    Some("prismatic") => DhJointType::Prismatic,
                    Some(other) => {
                        errors.push(
                            Error::unknown_value_with_alts(other, ["revolute", "prismatic"].iter())
                                .at(format!("joint {}", i + 1)),
                        );
                        DhJointType::Revolute
                    }
                };
                DhRow {
                    name: row.name.clone(),
                    link: row.link.clone(),
                    kind,
                    a: number(&row.a),
                    alpha: row.alpha.clone().map(|n| n.0).unwrap_or_default(),
                    d: number(&row.d),
                    theta: row.theta.clone().map(|n| n.0).unwrap_or_default(),
                    offset: row.offset.clone().map(|n| n.0).unwrap_or_default(),
                    lower: row.lower.clone().map(|n| n.0),
                    upper: row.upper.clone().map(|n| n.0),
                    velocity: row.velocity,
                    effort: row.effort,
                }
            })
            .collect();
        let fixed = |f: &InlineFixed, default_name: &str| DhFixed {
            name: f.name.clone().unwrap_or_else(|| default_name.to_owned()),
            xyz: f
                .xyz
                .as_ref()
                .map_or([0.0; 3], |t| t.0.clone().map(|v| if let Value::Number(x) = v { x } else { 0.0 })),
            rpy: f.rpy.as_ref().map_or_else(Default::default, |t| t.0.clone()),
        };
        let table = DhTable {
            name: self.name.clone().unwrap_or_else(|| "robot".to_owned()),
            convention,
            angle_unit,
            base_link: self.base_link.clone().unwrap_or_else(|| "base".to_owned()),
            base: self.base.as_ref().map(|b| fixed(b, "base")),
            tool: self.tool.as_ref().map(|t| fixed(t, "tool")),
            joints,
        };
        errors.finish_with(table)
    }
}
