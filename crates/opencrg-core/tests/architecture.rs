//! The structure the code promises (ARCHITECTURE.md), read from the sources' `crate::`
//! paths: every such path names a module (never an item of the crate's root, whose
//! re-exports are for the crate's users), no two modules of a crate use each other
//! (directly or in a circle), and in the layered crates (the evaluator, the toolkit) each
//! module uses only its own layer and those below it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The workspace's crates, by folder under `crates/`.
const CRATES: [&str; 11] = [
    "opencrg-core",
    "opencrg-tools",
    "opencrg-odr",
    "opencrg-fmu",
    "opencrg-fmi",
    "opencrg-sys",
    "opencrg-cli",
    "opencrg-python",
    "opencrg-difftest",
    "opencrg-wasm",
    "opencrg-capi",
];

/// A module: its name (the file's stem, or its folder's for `mod.rs`), its folder under
/// `src`, and its file.
struct Module {
    name: String,
    folder: String,
    path: PathBuf,
}

/// Every module under `src` but the crate's root (`lib.rs`, `main.rs`).
fn modules(src: &Path) -> Vec<Module> {
    let mut out = Vec::new();
    let mut dirs = vec![src.to_path_buf()];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            let root = path.parent() == Some(src) && (path.ends_with("lib.rs") || path.ends_with("main.rs"));
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") && !root {
                let folder = path.parent().unwrap().strip_prefix(src).unwrap().to_string_lossy().into_owned();
                let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
                let name = if stem == "mod" { folder.rsplit('/').next().unwrap().to_string() } else { stem };
                out.push(Module { name, folder, path });
            }
        }
    }
    out.sort_by(|a, b| a.path.cmp(&b.path));
    out
}

/// A source's code: its unit tests and its comment lines left out.
fn code(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    let body = text.split("#[cfg(test)]\nmod tests").next().unwrap().to_string();
    body.lines().filter(|l| !l.trim_start().starts_with("//")).collect::<Vec<_>>().join("\n")
}

/// The `crate::` paths of some code, each as its segments (`crate::{a, b::c}` names two).
fn crate_paths(code: &str) -> Vec<Vec<String>> {
    // A path's segments: the text up to the first character no path holds.
    let segments = |p: &str| -> Vec<String> {
        let p = p.trim_start();
        let end = p.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == ':')).unwrap_or(p.len());
        p[..end].split("::").take_while(|s| !s.is_empty()).map(str::to_string).collect()
    };
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(at) = rest.find("crate::") {
        // `$crate::` in a macro, `opencrg_core::` and the like are other crates' paths.
        let before = rest[..at].chars().last();
        rest = &rest[at + "crate::".len()..];
        if before.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_' || c == '$') {
            continue;
        }
        if let Some(group) = rest.strip_prefix('{') {
            let inner = &group[..group.find('}').unwrap_or(group.len())];
            out.extend(inner.split(',').map(segments).filter(|s| !s.is_empty()));
        } else {
            out.push(segments(rest));
        }
    }
    out
}

/// A crate's structure: its modules, the folders that hold them, and which modules each
/// module uses; failing on a path that names no module.
struct Structure {
    modules: Vec<Module>,
    uses: BTreeMap<String, BTreeSet<String>>,
}

fn structure(krate: &str) -> Structure {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(krate).join("src");
    assert!(
        src.join("lib.rs").exists() || src.join("main.rs").exists(),
        "{krate}: no crate root under {}",
        src.display()
    );
    let modules = modules(&src);
    let names: BTreeSet<&str> = modules.iter().map(|m| m.name.as_str()).collect();
    let folders: BTreeSet<&str> = modules.iter().flat_map(|m| m.folder.split('/')).filter(|f| !f.is_empty()).collect();
    let mut uses = BTreeMap::new();
    let roots = ["lib.rs", "main.rs"].map(|r| src.join(r));
    for (file, name) in modules
        .iter()
        .map(|m| (m.path.clone(), Some(m.name.clone())))
        .chain(roots.iter().filter(|r| r.exists()).map(|r| (r.clone(), None)))
    {
        let mut used = BTreeSet::new();
        for path in crate_paths(&code(&file)) {
            // The module a path names: its last segment that is a module; the ones before
            // it must be folders or modules, from the first on.
            let reached = path.iter().take_while(|s| names.contains(s.as_str()) || folders.contains(s.as_str()));
            let module = reached.filter(|s| names.contains(s.as_str())).last();
            match module {
                Some(m) => {
                    used.insert(m.clone());
                }
                None if path.first().is_some_and(|s| folders.contains(s.as_str())) => {}
                None => panic!(
                    "{krate}: {} uses crate::{}: an item of the crate's root, not a module (write the module's path)",
                    file.display(),
                    path.join("::")
                ),
            }
        }
        if let Some(name) = name {
            used.remove(&name);
            uses.insert(name, used);
        }
    }
    Structure { modules, uses }
}

/// A circle of modules, if any.
fn circle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        path: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(at) = path.iter().position(|n| n == node) {
            let mut found = path[at..].to_vec();
            found.push(node.to_string());
            return Some(found);
        }
        if done.contains(node) {
            return None;
        }
        path.push(node.to_string());
        for next in graph.get(node).into_iter().flatten() {
            if let Some(c) = visit(next, graph, path, done) {
                return Some(c);
            }
        }
        path.pop();
        done.insert(node.to_string());
        None
    }
    let mut done = BTreeSet::new();
    graph.keys().find_map(|k| visit(k, graph, &mut Vec::new(), &mut done))
}

#[test]
fn crate_paths_name_modules_and_no_modules_use_each_other() {
    for krate in CRATES {
        let s = structure(krate);
        if let Some(c) = circle(&s.uses) {
            panic!("{krate}: modules in a circle: {}", c.join(" -> "));
        }
    }
}

/// Each module of a layered crate uses only its own layer and those below it; `rank`
/// gives a folder's layer.
fn layered(krate: &str, rank: impl Fn(&str) -> u32, apart: &[(&str, &str)]) {
    let s = structure(krate);
    // A folder inside a layer's folder (a module's own submodules) is of that layer.
    let top = |folder: &str| folder.split('/').next().unwrap_or_default().to_string();
    let layer: BTreeMap<&str, String> = s.modules.iter().map(|m| (m.name.as_str(), top(&m.folder))).collect();
    for m in &s.modules {
        let own = top(&m.folder);
        for used in &s.uses[&m.name] {
            let theirs = layer[used.as_str()].as_str();
            assert!(
                rank(theirs) <= rank(&own),
                "{krate}: {}/{} uses {theirs}/{used}, a layer above its own",
                m.folder,
                m.name
            );
            for &(a, b) in apart {
                assert!(
                    !(own == a && theirs == b || own == b && theirs == a),
                    "{krate}: {}/{} uses {theirs}/{used}: {a} and {b} stand beside each other",
                    m.folder,
                    m.name
                );
            }
        }
    }
}

#[test]
fn the_evaluators_modules_use_only_lower_layers() {
    // The folders of src/, bottom up; files directly in src/ (synth) sit on top.
    layered(
        "opencrg-core",
        |folder| match folder {
            "base" => 0,
            "model" => 1,
            "read" | "write" => 2,
            "parts" | "query" | "geo" => 3,
            "" => 4,
            other => panic!("opencrg-core: src/{other}: a folder that is not a layer of ARCHITECTURE.md"),
        },
        &[("read", "write"), ("parts", "query"), ("parts", "geo"), ("query", "geo")],
    );
}

#[test]
fn the_toolkits_modules_use_only_lower_layers() {
    layered(
        "opencrg-tools",
        |folder| match folder {
            "analysis" | "export" => 0,
            "make" => 1,
            other => panic!("opencrg-tools: src/{other}: a folder that is not a layer of ARCHITECTURE.md"),
        },
        &[("analysis", "export")],
    );
}

#[test]
fn a_path_to_a_root_item_is_found() {
    let paths = crate_paths("use crate::{Road, model::grid::Grid};\nlet x = $crate::y::z; other_crate::w;");
    assert_eq!(paths, vec![vec!["Road".to_string()], vec!["model".into(), "grid".into(), "Grid".into()]]);
}

/// The functions of a source (outside its unit tests) longer than `limit` lines, as
/// `name (lines)`: a function runs from its `fn` line to the first `}` at that line's
/// indentation (the code is formatted by rustfmt).
fn long_functions(text: &str, limit: usize) -> Vec<String> {
    let lines: Vec<&str> = text.split("#[cfg(test)]\nmod tests").next().unwrap().lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let trimmed = line.trim_start();
        let Some(at) = trimmed.find("fn ") else { continue };
        let head = &trimmed[..at];
        let is_fn = head.split_whitespace().all(|w| {
            matches!(w, "pub" | "pub(crate)" | "pub(super)" | "const" | "unsafe" | "async" | "extern" | "\"C\"")
        });
        if !is_fn || trimmed.starts_with("//") || line.trim_end().ends_with(';') {
            continue;
        }
        let indent = &line[..line.len() - trimmed.len()];
        let close = format!("{indent}}}");
        let Some(end) = lines[i..].iter().position(|l| l.trim_end() == close) else { continue };
        if end + 1 > limit {
            let name = trimmed[at + 3..].split(|c: char| !c.is_alphanumeric() && c != '_').next().unwrap_or("");
            out.push(format!("{name} ({} lines)", end + 1));
        }
    }
    out
}

/// Every Rust source under `src` (the crate's root too), with its text.
fn sources(src: &Path) -> Vec<(PathBuf, String)> {
    let mut out = Vec::new();
    let mut dirs = vec![src.to_path_buf()];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(&path).unwrap();
                out.push((path, text));
            }
        }
    }
    out
}

#[test]
fn no_function_outside_tests_is_longer_than_100_lines() {
    let mut long = Vec::new();
    for krate in CRATES {
        let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(krate).join("src");
        for (path, text) in sources(&src) {
            long.extend(long_functions(&text, 100).into_iter().map(|f| format!("{}: {f}", path.display())));
        }
    }
    long.sort();
    assert!(long.is_empty(), "functions over 100 lines:\n{}", long.join("\n"));
}

#[test]
fn a_long_function_is_found() {
    let body = "    let a = 1;\n".repeat(101);
    let text = format!("pub(crate) fn long(x: u8) -> u8 {{\n{body}}}\nfn short() {{\n}}\n");
    assert_eq!(long_functions(&text, 100), vec!["long (103 lines)"]);
    assert!(long_functions(&text, 103).is_empty());
    let in_tests = format!("#[cfg(test)]\nmod tests {{\n{text}}}\n");
    assert!(long_functions(&in_tests, 100).is_empty());
}

#[test]
fn the_evaluator_hides_no_public_item() {
    for (path, text) in sources(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src")) {
        assert!(
            !text.contains("#[doc(hidden)]"),
            "{}: an item hidden from the documentation (public API is documented, the rest is not public)",
            path.display()
        );
    }
}
