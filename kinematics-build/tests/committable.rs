//! `kinematics generate -o` output can be committed (issue 13): the generated file holds no path
//! of the machine that generated it (the description's text is embedded, exactly), and it is
//! written with ordinary permissions, not a temporary file's owner-only ones.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics_build::Robot;

/// A scratch directory holding `files`.
fn fixture(test: &str, files: &[(&str, &str)]) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("kinematics-build-committable-{test}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for (name, text) in files {
        std::fs::write(dir.join(name), text).unwrap();
    }
    dir
}

/// A URDF whose text a careless embedding would break: quotes followed by `#`, backslashes.
const ARM: &str = r###"<robot name="arm">
  <!-- "#" and "## and \n and \" are text, not escapes -->
  <link name="base"/> <link name="tool"/>
  <joint name="j" type="continuous"><parent link="base"/><child link="tool"/>
    <origin xyz="1 0 0"/><axis xyz="0 0 1"/></joint>
</robot>
"###;

/// The string literal `reference()` parses, read back from the generated file.
fn embedded_text(source: &str) -> String {
    let file = syn::parse_file(source).unwrap();
    let found = file.items.iter().find_map(|item| {
        let syn::Item::Const(c) = item else { return None };
        let syn::Expr::Block(block) = &*c.expr else { return None };
        block.block.stmts.iter().find_map(|stmt| {
            let syn::Stmt::Item(syn::Item::Impl(imp)) = stmt else { return None };
            imp.items.iter().find_map(|item| {
                // `reference()` stands in the facade's `with_std! { ... }`.
                let syn::ImplItem::Macro(m) = item else { return None };
                let f: syn::ImplItemFn = syn::parse2(m.mac.tokens.clone()).ok()?;
                if f.sig.ident != "reference" || imp.trait_.is_some() {
                    return None;
                }
                let Some(syn::Stmt::Expr(syn::Expr::MethodCall(call), _)) = f.block.stmts.last() else { return None };
                let syn::Expr::Call(parse) = &*call.receiver else { return None };
                match parse.args.iter().nth(1) {
                    Some(syn::Expr::Lit(syn::ExprLit { lit: syn::Lit::Str(s), .. })) => Some(s.value()),
                    _ => None,
                }
            })
        })
    });
    found.unwrap_or_else(|| panic!("no description text in\n{source}"))
}

#[test]
fn the_file_embeds_the_description_and_no_path() {
    for (name, text) in [("arm.urdf", ARM.to_owned()), ("crlf.urdf", ARM.replace('\n', "\r\n"))] {
        let dir = fixture("paths", &[(name, &text)]);
        let source = Robot::urdf(name).manifest_dir(&dir).tip("tool").generate().unwrap();
        let dir_text = dir.to_string_lossy();
        assert!(!source.contains(&*dir_text), "{name}: the generating machine's path is in\n{source}");
        assert!(!source.contains("include_str"), "{source}");
        assert_eq!(embedded_text(&source), text, "{name}");
        // Readable: the lines of the description are lines of the file (no CR to keep there).
        if !text.contains('\r') {
            assert!(source.contains(ARM), "{source}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

#[test]
fn the_same_description_elsewhere_generates_the_same_file() {
    let one = fixture("here", &[("arm.urdf", ARM)]);
    let other = fixture("there", &[("arm.urdf", ARM)]);
    let generate = |dir: &std::path::Path| Robot::urdf("arm.urdf").manifest_dir(dir).tip("tool").generate().unwrap();
    assert_eq!(generate(&one), generate(&other));
    std::fs::remove_dir_all(&one).unwrap();
    std::fs::remove_dir_all(&other).unwrap();
}

#[cfg(unix)]
#[test]
fn written_files_have_ordinary_permissions() {
    use std::os::unix::fs::PermissionsExt as _;
    let dir = fixture("mode", &[("arm.urdf", ARM)]);
    // What any new file gets here: 0o666 less the umask.
    let plain = dir.join("plain.rs");
    std::fs::write(&plain, "").unwrap();
    let ordinary = std::fs::metadata(&plain).unwrap().permissions().mode() & 0o777;
    let out = dir.join("arm.rs");
    Robot::urdf("arm.urdf").manifest_dir(&dir).tip("tool").write_to(&out).unwrap();
    let mode = std::fs::metadata(&out).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, ordinary, "generated file mode {mode:o}, ordinary {ordinary:o}");
    assert_ne!(mode & 0o044, 0, "readable by others under the usual umask: {mode:o}");
    // Rewritten with other contents, still ordinary.
    Robot::urdf("arm.urdf").manifest_dir(&dir).tip("tool").positions().write_to(&out).unwrap();
    assert_eq!(std::fs::metadata(&out).unwrap().permissions().mode() & 0o777, ordinary);
    std::fs::remove_dir_all(&dir).unwrap();
}
