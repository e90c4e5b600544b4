//! The structure the code promises (ARCHITECTURE.md), read from the sources' `crate::`
//! paths: no two modules of a crate use each other (directly or in a circle), and in the
//! core each module uses only its own layer and those below it, `read` and `write`
//! never each other.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Module name (file stem) and folder of every `.rs` file under `src`, but `lib.rs`.
fn modules(src: &Path) -> Vec<(String, String, PathBuf)> {
    let mut out = Vec::new();
    let mut dirs = vec![src.to_path_buf()];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") && !path.ends_with("lib.rs") {
                let name = path.file_stem().unwrap().to_string_lossy().into_owned();
                let folder = path.parent().unwrap().strip_prefix(src).unwrap().to_string_lossy().into_owned();
                out.push((name, folder, path));
            }
        }
    }
    out.sort();
    out
}

/// The modules a source file names through `crate::`, its unit tests left out.
fn uses(path: &Path, known: &BTreeSet<String>) -> BTreeSet<String> {
    let text = std::fs::read_to_string(path).unwrap();
    let code = text.split("#[cfg(test)]\nmod tests").next().unwrap();
    let mut found = BTreeSet::new();
    let mut rest = code;
    while let Some(at) = rest.find("crate::") {
        rest = &rest[at + "crate::".len()..];
        // `crate::{a, b::c}` names several.
        let names: Vec<&str> = if let Some(group) = rest.strip_prefix('{') {
            let inner = &group[..group.find('}').unwrap_or(group.len())];
            inner.split(',').map(|s| s.trim().split("::").next().unwrap_or("")).collect()
        } else {
            vec![rest.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).next().unwrap_or("")]
        };
        found.extend(names.into_iter().filter(|n| known.contains(*n)).map(str::to_string));
    }
    found
}

/// The use graph of a crate: module -> modules it uses (itself left out).
fn graph(src: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let mods = modules(src);
    let known: BTreeSet<String> = mods.iter().map(|m| m.0.clone()).collect();
    mods.iter()
        .map(|(name, _, path)| {
            let mut used = uses(path, &known);
            used.remove(name);
            (name.clone(), used)
        })
        .collect()
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

fn crate_src(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(name).join("src")
}

#[test]
fn no_crate_has_modules_that_use_each_other() {
    for krate in ["opencrg", "opencrg-sys", "opencrg-cli", "opencrg-difftest", "opencrg-python", "opencrg-odr"] {
        let g = graph(&crate_src(krate));
        assert!(g.len() > 2, "{krate}: sources not found");
        if let Some(c) = circle(&g) {
            panic!("{krate}: modules in a circle: {}", c.join(" -> "));
        }
    }
}

#[test]
fn core_modules_use_only_lower_layers() {
    // The folders of src/, bottom up; files directly in src/ (synth) sit on top.
    let rank = |folder: &str| match folder {
        "base" => 0,
        "model" => 1,
        "read" | "write" => 2,
        "query" | "geo" => 3,
        "analysis" | "export" | "" => 4,
        "tools" => 5,
        other => panic!("src/{other}: a folder that is not a layer of ARCHITECTURE.md"),
    };
    let src = crate_src("opencrg");
    let mods = modules(&src);
    let folder_of: BTreeMap<String, String> = mods.iter().map(|m| (m.0.clone(), m.1.clone())).collect();
    let mut wrong = Vec::new();
    for (name, used) in graph(&src) {
        let from = &folder_of[&name];
        for to in used {
            let target = &folder_of[&to];
            let sideways = from != target && rank(from) == rank(target);
            if rank(target) > rank(from) || sideways {
                wrong.push(format!("{from}/{name} uses {target}/{to}"));
            }
        }
    }
    assert!(wrong.is_empty(), "uses against the layers:\n{}", wrong.join("\n"));
}

#[test]
fn the_checker_finds_a_circle() {
    let g: BTreeMap<String, BTreeSet<String>> = [("a", "b"), ("b", "c"), ("c", "a")]
        .iter()
        .map(|(k, v)| (k.to_string(), BTreeSet::from([v.to_string()])))
        .collect();
    assert_eq!(circle(&g), Some(vec!["a".into(), "b".into(), "c".into(), "a".into()]));
}
