//! One DH schema: what the file format accepts in each column, and the checks the derive's inline
//! table shares with it (`dh::number`, `dh::check_angle`). Issue 13: an inline row
//! `row("j", "1.0", 0.0, "0.5", 0.0)` compiled with a = 0 and d = 0, while the same strings in a
//! TOML file were an error.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics_model::Element;
use kinematics_model::dh::{Value, check_angle, number};
use kinematics_model::parse_source;

fn row() -> Element {
    Element::DhRow { row: 1, joint: "j".to_owned() }
}

fn text(t: &str) -> Value {
    Value::Text(t.to_owned())
}

#[test]
fn number_columns_refuse_text_naming_row_column_and_value() {
    for (field, written) in [("a", "1.0"), ("d", "0.5"), ("velocity", "2"), ("effort", "pi"), ("x", "")] {
        let error = number(&text(written), &row(), field).unwrap_err();
        assert_eq!(
            error.to_string(),
            format!("DH row 1 (joint `j`): `{field}` = \"{written}\" must be a number, not text")
        );
    }
    assert_eq!(number(&Value::Number(-0.425), &row(), "a").ok(), Some(-0.425));
    let tool = Element::DhSection("tool");
    assert_eq!(
        number(&text("0.1"), &tool, "z").unwrap_err().to_string(),
        "DH `tool` transform: `z` = \"0.1\" must be a number, not text"
    );
}

#[test]
#[allow(clippy::approx_constant)] // a decimal that merely resembles pi/2 stays a number
fn angle_columns_take_numbers_and_exact_text_only() {
    for exact in ["pi/2", "-pi", "3pi/4", "0", "pi"] {
        assert!(check_angle(&text(exact), &row(), "alpha").is_ok(), "{exact}");
    }
    assert!(check_angle(&Value::Number(1.5708), &row(), "alpha").is_ok());
    for wrong in ["pie/2", "1.5708", "pi/2.0", "", "90deg"] {
        let error = check_angle(&text(wrong), &row(), "theta").unwrap_err();
        assert_eq!(
            error.to_string(),
            format!("DH row 1 (joint `j`): `theta` = \"{wrong}\" is neither a number nor an exact angle like \"pi/2\"")
        );
    }
}

/// The file format refuses the same cells, by the same rules where its types let a string in.
#[test]
fn the_file_format_refuses_the_same_cells() {
    let table = |row: &str| format!("convention = \"standard\"\n[[joints]]\nname = \"j\"\n{row}\n");
    let refused = |row: &str| parse_source("arm.toml", &table(row)).unwrap_err().to_string();
    // Lengths, velocity and effort are numbers by type.
    for row in ["a = \"1.0\"", "d = \"0.5\"", "velocity = \"2\"", "effort = \"1\""] {
        let message = refused(row);
        assert!(message.starts_with("arm.toml: line 4: invalid type: string"), "{row}: {message}");
    }
    // A prismatic joint's offset and limits are lengths; a revolute joint's are angles.
    assert_eq!(
        refused("type = \"prismatic\"\noffset = \"0.1\""),
        "arm.toml: DH row 1 (joint `j`): `offset` = \"0.1\" must be a number, not text"
    );
    assert_eq!(
        refused("type = \"prismatic\"\nlower = \"-pi\"\nupper = 1.0"),
        "arm.toml: DH row 1 (joint `j`): `lower` = \"-pi\" must be a number, not text"
    );
    assert!(parse_source("arm.toml", &table("lower = \"-pi\"\nupper = \"pi\"")).is_ok());
    assert_eq!(
        refused("alpha = \"pie/2\""),
        "arm.toml: DH row 1 (joint `j`): `alpha` = \"pie/2\" is neither a number nor an exact angle like \"pi/2\""
    );
}
