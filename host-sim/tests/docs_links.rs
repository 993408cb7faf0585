//! The user documentation is in the repository (`docs/`): every relative link
//! of the README, `docs/*.md` and `examples/logs/README.md` points to a file
//! that exists, and every `docs/…` page that `crane-sim --help` names exists.
use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The targets of the Markdown links `[text](target)` of a page.
fn links(md: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = md;
    while let Some(i) = rest.find("](") {
        rest = &rest[i + 2..];
        if let Some(end) = rest.find(')') {
            out.push(rest[..end].to_string());
            rest = &rest[end..];
        }
    }
    out
}

#[test]
fn documentation_links_point_to_files_that_exist() {
    let root = root();
    let mut pages = vec![root.join("README.md"), root.join("examples/logs/README.md")];
    let docs: Vec<PathBuf> = std::fs::read_dir(root.join("docs")).expect("docs/ exists").map(|e| e.unwrap().path()).collect();
    for page in ["README.md", "install.md", "cli.md", "log-format.md", "calibration.md", "reports.md", "model.md", "limiter.md"] {
        assert!(docs.contains(&root.join("docs").join(page)), "docs/{page} is missing");
    }
    pages.extend(docs.into_iter().filter(|p| p.extension().is_some_and(|e| e == "md")));
    let mut checked = 0;
    for page in &pages {
        let text = std::fs::read_to_string(page).unwrap();
        assert!(!text.contains("shared/SPEC"), "{} sends users to a file they do not have", page.display());
        for link in links(&text) {
            if link.starts_with("http") || link.starts_with('#') {
                continue;
            }
            let file = link.split('#').next().unwrap();
            let target = page.parent().unwrap().join(file);
            assert!(target.exists(), "{}: link {link} points to nothing", page.display());
            checked += 1;
        }
    }
    assert!(checked >= 20, "only {checked} links checked");
}

#[test]
fn help_points_to_pages_that_exist() {
    let out = Command::new(env!("CARGO_BIN_EXE_crane-sim")).arg("--help").output().unwrap();
    let help = String::from_utf8_lossy(&out.stdout).into_owned();
    let mut named = 0;
    for word in help.split(|c: char| c.is_whitespace() || c == '(' || c == ')' || c == ';' || c == ',') {
        let word = word.trim_end_matches([':', '.']);
        if word.starts_with("docs/") {
            assert!(root().join(word).is_file(), "--help names {word}, which does not exist");
            named += 1;
        }
    }
    assert!(named >= 3, "--help names {named} documentation pages: {help}");
    assert!(!help.contains("SPEC"), "{help}");
}
