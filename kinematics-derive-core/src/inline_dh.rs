//! A DH table written in the attribute, as in a textbook: the convention, then one row per joint.
//!
//! ```text
//! dh(convention = "standard",
//!    joint(name = "shoulder_pan", d = 0.089159, alpha = "pi/2"),
//!    joint(name = "shoulder_lift", a = -0.425),
//!    joint(name = "slide", type = "prismatic", offset = 0.1, lower = 0.0, upper = 0.5))
//! ```
//!
//! Keys and meanings are those of a DH file (see `kinematics_model::dh`), and so are the types: the
//! table becomes the file format's `DhTable` and `DhRow`s, and every cell is checked by the model's
//! own rules (`kinematics_model::dh::number`, `check_angle`), so a string in a length column (`a`,
//! `d`, `velocity`, `effort`, a prismatic joint's `offset`, `lower`, `upper`, an `xyz`) or an angle
//! string that is not exact is refused with the row, the column and the value, spanned on the cell.
//! Numbers may be negative; angles may be exact strings such as `"pi/2"`.
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
use kinematics_model::Element;
use kinematics_model::dh::{AngleUnit, DhConvention, DhFixed, DhJointType, DhRow, DhTable, Value, check_angle, number};
use proc_macro2::Span;

/// What the messages of the inline table call it.
pub const LABEL: &str = "inline DH table";

/// A cell: a number (negative numbers included) or a string, with the span of what was written.
#[derive(Debug, Clone)]
pub struct Number {
    /// The value, in the DH file format's terms.
    pub value: Value,
    /// Where it was written.
    pub span: Span,
}

impl FromMeta for Number {
    fn from_value(lit: &syn::Lit) -> darling::Result<Self> {
        let value = match lit {
            syn::Lit::Float(f) => f.base10_parse::<f64>().map(Value::Number).map_err(Error::from),
            syn::Lit::Int(i) => i.base10_parse::<f64>().map(Value::Number).map_err(Error::from),
            syn::Lit::Str(s) => Ok(Value::Text(s.value())),
            _ => Err(Error::unexpected_lit_type(lit)),
        }
        .map_err(|e| e.with_span(lit))?;
        Ok(Number { value, span: lit.span() })
    }

    fn from_expr(expr: &syn::Expr) -> darling::Result<Self> {
        match expr {
            syn::Expr::Lit(lit) => Self::from_value(&lit.lit),
            syn::Expr::Group(group) => Self::from_expr(&group.expr),
            syn::Expr::Unary(syn::ExprUnary { op: syn::UnOp::Neg(_), expr: inner, .. }) => {
                let Number { value, .. } = Self::from_expr(inner)?;
                let span = syn::spanned::Spanned::span(expr);
                Ok(Number {
                    value: match value {
                        Value::Number(x) => Value::Number(-x),
                        Value::Text(t) => Value::Text(format!("-{t}")),
                    },
                    span,
                })
            }
            _ => Err(Error::unexpected_expr_type(expr).with_span(expr)),
        }
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
    velocity: Option<Number>,
    #[darling(default)]
    effort: Option<Number>,
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
        let Some(Number { value: Value::Text(name), .. }) = values.first().cloned() else {
            return Err(Error::custom(usage));
        };
        let mut rest = values[1..].to_vec();
        let mut kind = None;
        if let Some(Number { value: Value::Text(t), .. }) = rest.first()
            && (t == "prismatic" || t == "revolute")
        {
            kind = Some(t.clone());
            rest.remove(0);
        }
        if rest.len() != 4 && rest.len() != 6 {
            return Err(Error::custom(format!("{usage}; found {} numbers", rest.len())));
        }
        let mut columns = rest.into_iter();
        let mut next = || columns.next();
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
pub struct Triple([Number; 3]);

impl FromMeta for Triple {
    fn from_list(items: &[NestedMeta]) -> darling::Result<Self> {
        let values: Vec<Number> = items
            .iter()
            .map(|item| match item {
                NestedMeta::Lit(lit) => Number::from_value(lit),
                other => Err(Error::custom("expected a number").with_span(other)),
            })
            .collect::<darling::Result<_>>()?;
        match <[Number; 3]>::try_from(values) {
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

/// A cell the model's rules refused; its error is already in the accumulator.
struct Refused;

/// Checks cells against the model's rules, gathering every fault spanned on its cell. Each check
/// gives `Ok(None)` for a cell not written (the file format's default applies, as when a DH file
/// leaves the key out).
struct Cells<'e> {
    errors: &'e mut darling::error::Accumulator,
}

impl Cells<'_> {
    fn refuse(&mut self, error: kinematics_model::LoadErrorKind, span: Span) -> Refused {
        self.errors.push(Error::custom(format!("{LABEL}: {error}")).with_span(&span));
        Refused
    }

    /// A column holding a plain number (a length, `velocity`, `effort`).
    fn number(&mut self, cell: Option<&Number>, element: &Element, field: &str) -> Result<Option<f64>, Refused> {
        let Some(cell) = cell else { return Ok(None) };
        number(&cell.value, element, field).map(Some).map_err(|e| self.refuse(e, cell.span))
    }

    /// An angle column: a number, or text that is an exact angle.
    fn angle(&mut self, cell: Option<&Number>, element: &Element, field: &str) -> Result<Option<Value>, Refused> {
        let Some(cell) = cell else { return Ok(None) };
        check_angle(&cell.value, element, field).map_err(|e| self.refuse(e, cell.span))?;
        Ok(Some(cell.value.clone()))
    }

    /// A column that is an angle for a revolute joint and a length for a prismatic one.
    fn either(
        &mut self,
        cell: Option<&Number>,
        kind: DhJointType,
        element: &Element,
        field: &str,
    ) -> Result<Option<Value>, Refused> {
        match kind {
            DhJointType::Revolute => self.angle(cell, element, field),
            DhJointType::Prismatic => Ok(self.number(cell, element, field)?.map(Value::Number)),
        }
    }
}

impl InlineDh {
    /// The table in the model's terms: the very `DhTable` a DH file deserialises into, every cell
    /// checked by the model's rules (all faults together, each spanned on its cell).
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
        let rows_given = rows.len();
        let mut joints = Vec::new();
        for (i, row) in rows.into_iter().enumerate() {
            let element = Element::DhRow { row: i + 1, joint: row.name.clone() };
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
            let mut cells = Cells { errors: &mut errors };
            // Every cell is checked before any `?`, so that all faults are reported.
            let (a, alpha, d, theta) = (
                cells.number(row.a.as_ref(), &element, "a"),
                cells.angle(row.alpha.as_ref(), &element, "alpha"),
                cells.number(row.d.as_ref(), &element, "d"),
                cells.angle(row.theta.as_ref(), &element, "theta"),
            );
            let (offset, lower, upper) = (
                cells.either(row.offset.as_ref(), kind, &element, "offset"),
                cells.either(row.lower.as_ref(), kind, &element, "lower"),
                cells.either(row.upper.as_ref(), kind, &element, "upper"),
            );
            let (velocity, effort) = (
                cells.number(row.velocity.as_ref(), &element, "velocity"),
                cells.number(row.effort.as_ref(), &element, "effort"),
            );
            let checked = || -> Result<DhRow, Refused> {
                // A column left out takes the file format's default (`#[serde(default)]`: zero).
                Ok(DhRow {
                    name: row.name.clone(),
                    link: row.link.clone(),
                    kind,
                    a: a?.unwrap_or_default(),
                    alpha: alpha?.unwrap_or_default(),
                    d: d?.unwrap_or_default(),
                    theta: theta?.unwrap_or_default(),
                    offset: offset?.unwrap_or_default(),
                    lower: lower?,
                    upper: upper?,
                    velocity: velocity?,
                    effort: effort?,
                })
            };
            if let Ok(row) = checked() {
                joints.push(row);
            }
        }
        let mut fixed = |f: &InlineFixed, section: &'static str| -> Result<DhFixed, Refused> {
            let element = Element::DhSection(section);
            let mut cells = Cells { errors: &mut errors };
            let no_cells = [None, None, None];
            let xyz = f.xyz.as_ref().map(|t| t.0.each_ref().map(Some)).unwrap_or(no_cells);
            let rpy = f.rpy.as_ref().map(|t| t.0.each_ref().map(Some)).unwrap_or(no_cells);
            let [x, y, z] =
                [(xyz[0], "x"), (xyz[1], "y"), (xyz[2], "z")].map(|(c, field)| cells.number(c, &element, field));
            let [roll, pitch, yaw] = [(rpy[0], "roll"), (rpy[1], "pitch"), (rpy[2], "yaw")]
                .map(|(c, field)| cells.angle(c, &element, field));
            // Left out, a coordinate or angle is zero, as in a DH file.
            Ok(DhFixed {
                // The file format's default name (a base's name is not used).
                name: f.name.clone().unwrap_or_else(|| "tool".to_owned()),
                xyz: [x?.unwrap_or_default(), y?.unwrap_or_default(), z?.unwrap_or_default()],
                rpy: [roll?.unwrap_or_default(), pitch?.unwrap_or_default(), yaw?.unwrap_or_default()],
            })
        };
        let base = self.base.as_ref().map(|b| fixed(b, "base")).transpose();
        let tool = self.tool.as_ref().map(|t| fixed(t, "tool")).transpose();
        let table = match (base, tool) {
            (Ok(base), Ok(tool)) if joints.len() == rows_given => Some(DhTable {
                name: self.name.clone().unwrap_or_else(|| "robot".to_owned()),
                convention,
                angle_unit,
                base_link: self.base_link.clone().unwrap_or_else(|| "base".to_owned()),
                base,
                tool,
                joints,
            }),
            // A refused cell, whose error is in the accumulator.
            _ => None,
        };
        errors
            .finish_with(table)?
            .ok_or_else(|| Error::custom(format!("{LABEL}: a cell was refused without a message; please report this")))
    }
}

#[cfg(test)]
mod tests {
    use darling::FromMeta;
    use darling::ast::NestedMeta;
    use kinematics_model::dh::{DhJointType, DhTable, Value, parse_dh_toml};
    use quote::quote;

    use super::InlineDh;

    /// The table written inside `dh(...)`, converted.
    fn table(tokens: proc_macro2::TokenStream) -> darling::Result<DhTable> {
        let items = NestedMeta::parse_meta_list(tokens).unwrap();
        InlineDh::from_list(&items)?.to_table()
    }

    /// Every message of a refused table, in order.
    fn refused(tokens: proc_macro2::TokenStream) -> Vec<String> {
        match table(tokens) {
            Ok(t) => panic!("accepted: {t:?}"),
            Err(e) => e.into_iter().map(|e| e.to_string()).collect(),
        }
    }

    #[test]
    fn strings_in_length_columns_are_refused_not_zero() {
        // Issue 13: this row compiled into a robot with a = 0 and d = 0.
        assert_eq!(
            refused(quote!(convention = "standard", row("j", "1.0", 0.0, "0.5", 0.0))),
            [
                "inline DH table: DH row 1 (joint `j`): `a` = \"1.0\" must be a number, not text",
                "inline DH table: DH row 1 (joint `j`): `d` = \"0.5\" must be a number, not text",
            ]
        );
        assert_eq!(
            refused(quote!(
                convention = "standard",
                joint(name = "s", a = 1.0),
                joint(name = "e", velocity = "2", effort = "x")
            )),
            [
                "inline DH table: DH row 2 (joint `e`): `velocity` = \"2\" must be a number, not text",
                "inline DH table: DH row 2 (joint `e`): `effort` = \"x\" must be a number, not text",
            ]
        );
        assert_eq!(
            refused(quote!(convention = "standard", tool(xyz(0, "0", 0.1)), row("j", 0.0, 0.0, 0.0, 0.0))),
            ["inline DH table: DH `tool` transform: `y` = \"0\" must be a number, not text"]
        );
    }

    #[test]
    fn angle_text_must_be_exact_and_prismatic_columns_are_lengths() {
        assert_eq!(
            refused(quote!(convention = "standard", row("j", 1.0, "pie/2", 0.0, "1.5708"))),
            [
                "inline DH table: DH row 1 (joint `j`): `alpha` = \"pie/2\" is neither a number nor an exact angle like \"pi/2\"",
                "inline DH table: DH row 1 (joint `j`): `theta` = \"1.5708\" is neither a number nor an exact angle like \"pi/2\"",
            ]
        );
        assert_eq!(
            refused(quote!(convention = "standard", row("slide", "prismatic", 0.0, 0.0, 0.1, 0.0, "-pi", 0.5))),
            ["inline DH table: DH row 1 (joint `slide`): `lower` = \"-pi\" must be a number, not text"]
        );
        assert_eq!(
            refused(quote!(convention = "standard", joint(name = "slide", type = "prismatic", offset = "0.1"))),
            ["inline DH table: DH row 1 (joint `slide`): `offset` = \"0.1\" must be a number, not text"]
        );
        assert_eq!(
            refused(quote!(convention = "standard", base(rpy(0, 0, "half")), row("j", 0.0, 0.0, 0.0, 0.0))),
            [
                "inline DH table: DH `base` transform: `yaw` = \"half\" is neither a number nor an exact angle like \"pi/2\""
            ]
        );
    }

    /// Every column of the file format is reachable inline, and gives the row the file gives.
    #[test]
    fn the_inline_table_is_the_file_formats_table() {
        let inline = table(quote!(
            convention = "modified",
            name = "arm",
            angle_unit = "degrees",
            base_link = "world",
            base(xyz(0, 0, 0.1), rpy(0, 0, "pi")),
            tool(name = "flange", xyz(0, 0, -0.107), rpy(90, 0, 0)),
            joint(name = "j1", link = "l1", a = -0.425, alpha = "pi/2", d = 0.089, theta = 30, offset = -90,
                  lower = -170, upper = 170, velocity = 2.5, effort = 150),
            joint(name = "j2", type = "prismatic", offset = 0.1, lower = 0, upper = 0.5, velocity = 0.2, effort = 40)
        ))
        .unwrap();
        let file = parse_dh_toml(
            r#"convention = "modified"
name = "arm"
angle_unit = "degrees"
base_link = "world"
base = { xyz = [0, 0, 0.1], rpy = [0, 0, "pi"] }
tool = { name = "flange", xyz = [0, 0, -0.107], rpy = [90, 0, 0] }
[[joints]]
name = "j1"
link = "l1"
a = -0.425
alpha = "pi/2"
d = 0.089
theta = 30
offset = -90
lower = -170
upper = 170
velocity = 2.5
effort = 150
[[joints]]
name = "j2"
type = "prismatic"
offset = 0.1
lower = 0
upper = 0.5
velocity = 0.2
effort = 40
"#,
        )
        .unwrap();
        assert_eq!(inline.to_toml().unwrap(), file.to_toml().unwrap());
        assert_eq!(inline.joints[1].kind, DhJointType::Prismatic);
        assert_eq!(inline.joints[0].alpha, Value::Text("pi/2".to_owned()));
    }
}
