//! A CRG file or an OpenDRIVE map packed as an FMU (FMI 2.0 or 3.0, model exchange and
//! co-simulation): the road and every file it needs in `resources/`, the model
//! description, and the binary of each platform at hand under `binaries/`.
//!
//! The files are laid out in `resources/` as they lie to each other, so that a CRG
//! file's references to other files (`$ROAD_CRG_FILE`), written relative to it, still
//! find them; a map's CRG
//! files each get a folder, and the resources' configuration says which record's file
//! went where. Before anything is written the road is loaded from the laid-out copy as
//! the FMU's binary will load it; the FMU is written to a temporary file and renamed,
//! so a refused road leaves nothing behind.

use opencrg_core::units::Count;
use opencrg_core::{Error, Result};
use opencrg_fmu::description::{identifier_of, model_description, Fmi, Meta};
use opencrg_fmu::{config, Config, Kind};
use std::io::Write;
use std::path::{Component, Path, PathBuf};

/// A platform an FMU's binary runs on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Platform {
    /// 64-bit x86 Linux.
    LinuxX86_64,
    /// 64-bit Arm Linux.
    LinuxAarch64,
    /// 64-bit x86 Windows.
    WindowsX86_64,
}

impl Platform {
    /// Every platform, in the order they are packed.
    pub const ALL: [Platform; 3] = [Platform::LinuxX86_64, Platform::LinuxAarch64, Platform::WindowsX86_64];

    /// FMI 3's platform tuple (the folder under `binaries/`, and under a folder of
    /// binaries the FMU packer reads).
    pub fn tuple(self) -> &'static str {
        match self {
            Platform::LinuxX86_64 => "x86_64-linux",
            Platform::LinuxAarch64 => "aarch64-linux",
            Platform::WindowsX86_64 => "x86_64-windows",
        }
    }

    /// The folder under `binaries/` of an FMU of version `fmi` (FMI 2 names no Arm
    /// platform: its binary goes where FMI 3 puts it).
    pub fn folder(self, fmi: Fmi) -> &'static str {
        match (fmi, self) {
            (Fmi::V2, Platform::LinuxX86_64) => "linux64",
            (Fmi::V2, Platform::WindowsX86_64) => "win64",
            _ => self.tuple(),
        }
    }

    /// The binary's file name as built (`libopencrg_fmi.so`, `opencrg_fmi.dll`).
    pub fn built_name(self) -> &'static str {
        match self {
            Platform::WindowsX86_64 => "opencrg_fmi.dll",
            _ => "libopencrg_fmi.so",
        }
    }

    /// The binary's extension in an FMU.
    pub fn extension(self) -> &'static str {
        match self {
            Platform::WindowsX86_64 => "dll",
            _ => "so",
        }
    }

    /// The platform this program runs on, if it is one of them.
    pub fn this() -> Option<Platform> {
        match (std::env::consts::ARCH, std::env::consts::OS) {
            ("x86_64", "linux") => Some(Platform::LinuxX86_64),
            ("aarch64", "linux") => Some(Platform::LinuxAarch64),
            ("x86_64", "windows") => Some(Platform::WindowsX86_64),
            _ => None,
        }
    }
}

/// One platform's binary.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Binary {
    /// The platform it runs on.
    pub platform: Platform,
    /// The file.
    pub file: PathBuf,
}

/// The binaries in a folder laid out as `TUPLE/FILE` (`x86_64-linux/libopencrg_fmi.so`,
/// `x86_64-windows/opencrg_fmi.dll`, `aarch64-linux/libopencrg_fmi.so`), as the release
/// archives hold them.
pub fn binaries_in(folder: &Path) -> Vec<Binary> {
    Platform::ALL
        .into_iter()
        .map(|platform| Binary { platform, file: folder.join(platform.tuple()).join(platform.built_name()) })
        .filter(|b| b.file.is_file())
        .collect()
}

/// What to pack.
#[derive(Debug, Clone)]
pub struct FmuOptions {
    /// How many wheels (1 to 999).
    pub wheels: u32,
    /// FMI 2.0 or 3.0.
    pub fmi: Fmi,
    /// The binaries to put in (at least one).
    pub binaries: Vec<Binary>,
    /// Whether a CRG file is left outside the FMU, named by its absolute path (a road of
    /// gigabytes is then read in place from where it lies, not copied into the zip); the
    /// FMU's `roadFile` parameter names another file where the road lies elsewhere.
    pub outside: bool,
}

/// What was packed.
#[derive(Debug, Clone)]
pub struct FmuReport {
    /// The model identifier (the binaries' name).
    pub identifier: String,
    /// The files put in `resources/` (the configuration among them).
    pub resources: Vec<String>,
    /// The platforms packed.
    pub platforms: Vec<Platform>,
    /// The number of variables.
    pub variables: usize,
}

/// A file to put in the FMU: its source and its path inside.
struct Entry {
    source: PathBuf,
    inside: String,
}

fn refused(why: String) -> Error {
    Error::out_of_range(why)
}

/// The folder that holds all of `folders` (absolute, canonical).
fn common_folder(folders: &[PathBuf]) -> PathBuf {
    let mut common = folders[0].clone();
    for p in &folders[1..] {
        while !p.starts_with(&common) {
            if !common.pop() {
                break;
            }
        }
    }
    common
}

/// The highest folder the written part of a reference passes through on its way up
/// (`../c/x.crg` from `a/b` passes through `a`), if it goes up at all: the layout in the
/// FMU must have it, so that the path, as written, still leads to the file. `files` are
/// the files as named (the CRG file and its references): the reference's own part is what
/// follows the folder of the file it was written in.
fn highest_on_the_way(reference: &Path, files: &[PathBuf]) -> Result<Option<PathBuf>> {
    let written_in = files
        .iter()
        .filter(|f| f.as_path() != reference)
        .filter_map(|f| f.parent())
        .filter(|folder| reference.starts_with(folder))
        .max_by_key(|folder| folder.components().count());
    let Some(folder) = written_in else { return Ok(None) };
    let rest = reference.strip_prefix(folder).unwrap_or(reference);
    let mut at = canonical(if folder.as_os_str().is_empty() { Path::new(".") } else { folder })?;
    let mut highest = None::<PathBuf>;
    for part in rest.components() {
        match part {
            Component::ParentDir => {
                at.pop();
                if highest.as_ref().is_none_or(|h| at.components().count() < h.components().count()) {
                    highest = Some(at.clone());
                }
            }
            Component::Normal(name) => at.push(name),
            _ => {}
        }
    }
    Ok(highest)
}

/// `path` below `folder`, written with `/`.
fn inside_of(path: &Path, folder: &Path) -> Result<String> {
    let rest = path
        .strip_prefix(folder)
        .map_err(|_| refused(format!("{}: not under {}", path.display(), folder.display())))?;
    let parts: Vec<String> = rest
        .components()
        .map(|c| match c {
            Component::Normal(part) => Ok(part.to_string_lossy().into_owned()),
            _ => Err(refused(format!("{}: a path the FMU cannot hold", path.display()))),
        })
        .collect::<Result<_>>()?;
    Ok(parts.join("/"))
}

fn canonical(path: &Path) -> Result<PathBuf> {
    std::fs::canonicalize(path).map_err(|e| Error::reading(path, e))
}

/// A CRG file and the files it references, laid out under `under` as they lie to each
/// other; the CRG file's own path inside.
fn crg_files(path: &Path, under: &str, entries: &mut Vec<Entry>) -> Result<String> {
    let road = opencrg_core::Road::load(path)?;
    let main = canonical(path)?;
    let mut all = vec![main.clone()];
    let mut folders: Vec<PathBuf> = main.parent().map(Path::to_path_buf).into_iter().collect();
    let named: Vec<PathBuf> =
        std::iter::once(path.to_path_buf()).chain(road.header().references.iter().cloned()).collect();
    for reference in &road.header().references {
        let file = canonical(reference)?;
        folders.extend(file.parent().map(Path::to_path_buf));
        folders.extend(highest_on_the_way(reference, &named)?);
        if !all.contains(&file) {
            all.push(file);
        }
    }
    let folder = common_folder(&folders);
    let mut main_inside = String::new();
    for file in &all {
        let inside = format!("{under}/{}", inside_of(file, &folder)?);
        if *file == main {
            main_inside = inside.clone();
        }
        entries.push(Entry { source: file.clone(), inside });
    }
    Ok(main_inside)
}

/// The files of the road in `road` and the configuration that names them (its token
/// still empty).
fn gather(road: &Path, kind: Kind, wheels: u32, outside: bool) -> Result<(Vec<Entry>, Config)> {
    let mut entries = Vec::new();
    let mut config = Config { token: String::new(), kind, road: String::new(), outside, wheels, crg: Vec::new() };
    match kind {
        Kind::Crg if outside => {
            opencrg_core::Road::load(road)?;
            config.road = canonical(road)?.to_string_lossy().into_owned();
        }
        Kind::Map if outside => {
            return Err(refused("a map's FMU holds its files: only a CRG file is left outside".into()))
        }
        Kind::Crg => config.road = crg_files(road, "road", &mut entries)?,
        Kind::Map => {
            let map = opencrg_odr::Map::load(road)?;
            let name = road.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "map.xodr".into());
            entries.push(Entry { source: road.to_path_buf(), inside: format!("road/{name}") });
            config.road = format!("road/{name}");
            let records = map.roads.iter().flat_map(|r| &r.crg).chain(map.junctions.iter().flat_map(|j| &j.crg));
            // Each file once, by where it is; each way the map writes it once.
            let mut placed: Vec<(PathBuf, String)> = Vec::new();
            for record in records {
                if config.crg.iter().any(|(file, _)| *file == record.file) {
                    continue;
                }
                let file = canonical(&record.path).map_err(|e| Error::Format {
                    path: map.path.clone(),
                    location: opencrg_core::Location::Line(record.line),
                    field: format!("<CRG> file '{}'", record.file),
                    message: e.to_string(),
                })?;
                let inside = match placed.iter().find(|(p, _)| *p == file) {
                    Some((_, inside)) => inside.clone(),
                    None => {
                        let inside = crg_files(&record.path, &format!("crg/{}", placed.len() + 1), &mut entries)?;
                        placed.push((file, inside.clone()));
                        inside
                    }
                };
                config.crg.push((record.file.clone(), inside));
            }
        }
    }
    Ok((entries, config))
}

/// FNV-1a, 64 bits, from `state`.
fn fnv(mut state: u64, bytes: &[u8]) -> u64 {
    for &b in bytes {
        state = (state ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
    }
    state
}

/// The token of an FMU: a GUID-like text from a hash of everything it holds but the
/// token itself, so the same road packed alike gets the same token.
fn token_of(parts: &[&[u8]]) -> String {
    let (mut a, mut b) = (0xcbf2_9ce4_8422_2325_u64, 0x6c62_272e_07bb_0142_u64);
    for part in parts {
        a = fnv(a, part);
        b = fnv(b, &(part.len() as u64).to_le_bytes());
        b = fnv(b, part);
    }
    let h = format!("{a:016x}{b:016x}");
    format!("{{{}-{}-{}-{}-{}}}", &h[..8], &h[8..12], &h[12..16], &h[16..20], &h[20..])
}

/// A folder of its own for laying the files out, removed when dropped.
struct Staging(PathBuf);

impl Staging {
    fn new(near: &Path) -> Result<Staging> {
        let base = std::env::temp_dir();
        let stem = near.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        for n in 0..1000 {
            let dir = base.join(format!("opencrg-fmu-{}-{n}-{stem}", std::process::id()));
            match std::fs::create_dir(&dir) {
                Ok(()) => return Ok(Staging(dir)),
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
                Err(e) => return Err(Error::writing(&dir, e)),
            }
        }
        Err(refused(format!("{}: no free folder for laying the FMU out", base.display())))
    }
}

impl Drop for Staging {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Packs the road in `road` (a `.xodr` map, else a CRG file) as an FMU in `out`.
/// Refused, with nothing written: a road (or a CRG file of a map) that cannot be read or
/// fails the C API's check, a reference that leads outside the files laid out, no
/// binary, a wheel count out of 1 to 999.
pub fn write_fmu(road: &Path, out: &Path, options: &FmuOptions) -> Result<FmuReport> {
    if !(1..=opencrg_fmu::variables::MAX_WHEELS).contains(&options.wheels) {
        return Err(refused(format!("{} wheels: 1 to {}", options.wheels, opencrg_fmu::variables::MAX_WHEELS)));
    }
    if options.binaries.is_empty() {
        return Err(refused("no FMU binary to pack (build opencrg-fmi, or name a folder of binaries)".into()));
    }
    let is_map = road.extension().is_some_and(|e| e.eq_ignore_ascii_case("xodr"));
    let kind = if is_map { Kind::Map } else { Kind::Crg };
    let (entries, mut config) = gather(road, kind, options.wheels, options.outside)?;

    // Laid out, hashed, and loaded as the binary will load it.
    let staging = Staging::new(road)?;
    let resources = staging.0.join("resources");
    std::fs::create_dir_all(&resources).map_err(|e| Error::writing(&resources, e))?;
    let mut contents: Vec<Vec<u8>> = Vec::new();
    for entry in &entries {
        let bytes = std::fs::read(&entry.source).map_err(|e| Error::reading(&entry.source, e))?;
        let to = Config::resolve(&resources, &entry.inside);
        if let Some(parent) = to.parent() {
            std::fs::create_dir_all(parent).map_err(|e| Error::writing(parent, e))?;
        }
        std::fs::write(&to, &bytes).map_err(|e| Error::writing(&to, e))?;
        contents.push(bytes);
    }
    let version = env!("CARGO_PKG_VERSION");
    let settings = format!("{kind:?} {} {:?} opencrg {version}", options.wheels, options.fmi);
    let mut hashed: Vec<&[u8]> = Vec::new();
    for (entry, bytes) in entries.iter().zip(&contents) {
        hashed.extend([entry.inside.as_bytes(), bytes.as_slice()]);
    }
    hashed.push(settings.as_bytes());
    if config.outside {
        hashed.push(config.road.as_bytes());
    }
    config.token = token_of(&hashed);
    let config_text = config.to_text();
    let config_file = resources.join(config::FILE_NAME);
    std::fs::write(&config_file, &config_text).map_err(|e| Error::writing(&config_file, e))?;
    // Loaded as the binary loads it: the variables and their start values are its own.
    let fmu = opencrg_fmu::Fmu::load(&resources)?;

    let name = road.file_stem().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let file_name = road.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let identifier = identifier_of(&name);
    let variables = fmu.variables(options.fmi == Fmi::V3);
    let description = description_of(kind, &file_name, options.wheels as usize, config.crg.len());
    let meta = Meta {
        model_name: name,
        identifier: identifier.clone(),
        token: config.token.clone(),
        description,
        generation_tool: format!("opencrg {version}"),
        roads: fmu.road_ids(),
    };
    let xml = model_description(options.fmi, kind, &meta, &variables);

    // Written beside `out` under another name, then renamed onto it.
    let partial = out.with_extension("fmu.partial");
    let mut files: Vec<(String, &[u8])> = vec![("modelDescription.xml".into(), xml.as_bytes())];
    for (entry, bytes) in entries.iter().zip(&contents) {
        files.push((format!("resources/{}", entry.inside), bytes));
    }
    files.push((format!("resources/{}", config::FILE_NAME), config_text.as_bytes()));
    let binaries: Vec<(String, &Path)> = options
        .binaries
        .iter()
        .map(|b| {
            let folder = b.platform.folder(options.fmi);
            (format!("binaries/{folder}/{identifier}.{}", b.platform.extension()), b.file.as_path())
        })
        .collect();
    let written = zip_to(&partial, &files, &binaries);
    if let Err(e) = written.and_then(|()| std::fs::rename(&partial, out).map_err(|e| Error::writing(out, e))) {
        let _ = std::fs::remove_file(&partial);
        return Err(e);
    }
    let mut resources: Vec<String> = entries.iter().map(|e| e.inside.clone()).collect();
    resources.push(config::FILE_NAME.into());
    Ok(FmuReport {
        identifier,
        resources,
        platforms: options.binaries.iter().map(|b| b.platform).collect(),
        variables: variables.len(),
    })
}

/// The model description's one-line description of a road's or a map's FMU.
fn description_of(kind: Kind, file_name: &str, wheels: usize, crg_files: usize) -> String {
    match kind {
        Kind::Crg => format!("OpenCRG road {file_name}: height, normal and friction under {}", Count(wheels, "wheel")),
        Kind::Map => format!(
            "OpenDRIVE map {file_name} with {}: height, normal and friction under {}",
            Count(crg_files, "CRG file"),
            Count(wheels, "wheel")
        ),
    }
}

/// Writes the zip at `partial`: `files` (name inside, bytes), then the `binaries` (name
/// inside, file), executable.
fn zip_to(partial: &Path, files: &[(String, &[u8])], binaries: &[(String, &Path)]) -> Result<()> {
    let file = std::fs::File::create(partial).map_err(|e| Error::writing(partial, e))?;
    let mut zip = zip::ZipWriter::new(std::io::BufWriter::new(file));
    let io = |e: std::io::Error| Error::writing(partial, e);
    let zipped = |e: zip::result::ZipError| Error::writing(partial, std::io::Error::other(e));
    // A fixed time for every entry: the same road packed alike gives the same bytes.
    let fixed = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated)
        .last_modified_time(zip::DateTime::default());
    for (inside, bytes) in files {
        zip.start_file(inside.as_str(), fixed).map_err(zipped)?;
        zip.write_all(bytes).map_err(io)?;
    }
    for (inside, source) in binaries {
        let bytes = std::fs::read(source).map_err(|e| Error::reading(source, e))?;
        zip.start_file(inside.as_str(), fixed.unix_permissions(0o755)).map_err(zipped)?;
        zip.write_all(&bytes).map_err(io)?;
    }
    zip.finish().map_err(zipped)?.flush().map_err(io)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens_are_guids_that_follow_the_content() {
        let t = token_of(&[b"a", b"bc"]);
        assert_eq!(t.len(), 38, "{t}");
        assert!(t.starts_with('{') && t.ends_with('}') && t.matches('-').count() == 4, "{t}");
        assert_eq!(t, token_of(&[b"a", b"bc"]));
        assert_ne!(t, token_of(&[b"ab", b"c"]));
    }

    #[test]
    fn files_keep_their_places_to_each_other() {
        let folders = [PathBuf::from("/a/b/c"), PathBuf::from("/a/b/d")];
        let folder = common_folder(&folders);
        assert_eq!(folder, Path::new("/a/b"));
        assert_eq!(inside_of(Path::new("/a/b/c/x.crg"), &folder).unwrap(), "c/x.crg");
        assert_eq!(common_folder(&folders[..1]), Path::new("/a/b/c"));
        let d = std::env::temp_dir().join(format!("opencrg-fmu-unit-{}", std::process::id()));
        std::fs::create_dir_all(d.join("a/b")).unwrap();
        let files = [d.join("a/b/top.crg")];
        assert_eq!(
            highest_on_the_way(&d.join("a/b/../b/up.crg"), &files).unwrap(),
            Some(canonical(&d.join("a")).unwrap())
        );
        assert_eq!(highest_on_the_way(&d.join("a/b/x.crg"), &files).unwrap(), None);
        let _ = std::fs::remove_dir_all(&d);
    }
}
