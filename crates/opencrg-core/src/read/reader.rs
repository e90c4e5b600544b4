//! Reading CRG files: sections, file references, options and modifiers from the
//! header, and the location of the data section.
//!
//! A `$ROAD_CRG_FILE` section names another CRG file that is read into the same road,
//! as if its lines stood where the section ends. Options and modifiers of the top file
//! always win; of the referenced files, the first that defines a section is used.

use crate::base::error::{Error, Location, Result};
use crate::base::mapped_file::MappedFile;
use crate::base::settings::{self, Accepts, Family};
use crate::model::header::{Channel, DataFormat, Header, RoadKey, OFFSET_KEYS, ROAD_KEYS};
use crate::read::map_section::{self, MapEntry};
use crate::read::syntax::{self, key_value, lookup, parse_f64_prefix, parse_i32_prefix, Section, Tag};
use std::path::{Path, PathBuf};

/// Deepest chain of file references followed.
pub const MAX_REFERENCE_DEPTH: usize = 16;

/// Keywords of `$ROAD_CRG_OPTS` that the reference knows but that change nothing (its
/// logging settings). Others it does not know, such as `CHECK_PRO` and `CHECK_WGS` of
/// the MATLAB tools, get the unknown-keyword warning, as the reference warns of them.
const IGNORED_OPTION_KEYWORDS: [&str; 7] =
    ["log_msgs", "log_eval", "log_eval_freq", "log_hist", "log_hist_freq", "log_stat", "log_stat_freq"];

/// The bytes of a file: memory-mapped when possible (a road read in place keeps the
/// mapping).
pub(crate) enum FileBytes {
    Mapped(std::sync::Arc<MappedFile>),
    Owned(Vec<u8>),
}

impl std::ops::Deref for FileBytes {
    type Target = [u8];
    fn deref(&self) -> &[u8] {
        match self {
            FileBytes::Mapped(m) => m.bytes(),
            FileBytes::Owned(v) => v,
        }
    }
}

impl FileBytes {
    /// Lets the system drop the mapped pages in `start..end` from this process's
    /// memory: they have been decoded and will not be read again (see
    /// [`crate::base::memory::release_mapped`]).
    pub(crate) fn release(&self, start: usize, end: usize) {
        if let FileBytes::Mapped(map) = self {
            map.release(start, end);
        }
    }

    /// Whether the bytes read so far can be trusted (a mapped file may have been cut
    /// short or changed meanwhile); the error names `path`.
    pub(crate) fn check(&self, path: &Path) -> Result<()> {
        match self {
            FileBytes::Mapped(map) => map.check().map_err(|f| Error::reading(path, f.into_io())),
            FileBytes::Owned(_) => Ok(()),
        }
    }
}

/// Where the data section is.
pub(crate) struct DataSource {
    pub path: PathBuf,
    pub bytes: FileBytes,
    pub offset: usize,
}

struct Loader<'a> {
    /// Files held in memory that references are read from (by name), instead of disk.
    files: Option<&'a [(String, Vec<u8>)]>,
    header: Header,
    /// Where each `$ROAD_CRG_MPRO` keyword stood, parallel to `header.mpro`.
    mpro_places: Vec<(PathBuf, usize)>,
    data: Option<DataSource>,
    option_level: Option<usize>,
    modifier_level: Option<usize>,
    stack: Vec<PathBuf>,
}

/// Reads the header of `path` (following file references) and locates the data.
pub(crate) fn read(path: &Path) -> Result<(Header, Option<DataSource>)> {
    let mut loader = Loader::new(path, None);
    loader.read_file(path, 0)?;
    loader.resolve_map()?;
    Ok((loader.header, loader.data))
}

/// Reads a CRG file held in memory; `name` is used in messages and to resolve
/// relative file references: from disk, or from `files` where given (see
/// [`Loader::read_reference`]).
pub(crate) fn read_bytes(
    bytes: Vec<u8>,
    name: &Path,
    files: Option<&[(String, Vec<u8>)]>,
) -> Result<(Header, Option<DataSource>)> {
    if bytes.is_empty() {
        return Err(Error::format(name, Location::File, "file", "is empty"));
    }
    let mut loader = Loader::new(name, files);
    let offset = loader.parse(name, &bytes, 0)?;
    loader.resolve_map()?;
    let data = match offset {
        Some(offset) => {
            if loader.data.is_some() {
                return Err(Error::format(name, Location::File, "data section", "a second data section was found"));
            }
            Some(DataSource { path: name.to_path_buf(), bytes: FileBytes::Owned(bytes), offset })
        }
        None => loader.data,
    };
    Ok((loader.header, data))
}

impl<'a> Loader<'a> {
    fn new(path: &Path, files: Option<&'a [(String, Vec<u8>)]>) -> Self {
        Loader {
            files,
            header: Header::new(path),
            mpro_places: Vec::new(),
            data: None,
            option_level: None,
            modifier_level: None,
            stack: Vec::new(),
        }
    }
}

fn open(path: &Path) -> Result<FileBytes> {
    let io = |source| Error::reading(path, source);
    let directory = || Error::format(path, Location::File, "file", "is a directory, not a CRG file");
    // (Windows refuses to open a directory as a file: the reason is told all the same.)
    let file = std::fs::File::open(path).map_err(|e| if path.is_dir() { directory() } else { io(e) })?;
    let meta = file.metadata().map_err(io)?;
    if meta.is_dir() {
        return Err(directory());
    }
    if meta.len() == 0 {
        return Err(Error::format(path, Location::File, "file", "is empty"));
    }
    match MappedFile::open(file) {
        Ok(map) => Ok(FileBytes::Mapped(std::sync::Arc::new(map))),
        Err(_) => std::fs::read(path).map(FileBytes::Owned).map_err(io),
    }
}

impl Loader<'_> {
    /// Resolves the `$ROAD_CRG_MPRO` keywords read into the header's map projection.
    fn resolve_map(&mut self) -> Result<()> {
        let entries: Vec<MapEntry> = (self.header.mpro.iter().zip(&self.mpro_places))
            .filter(|((k, _), _)| map_section::is_keyword(k))
            .map(|((key, value), (path, line))| MapEntry { key, value, path, line: *line })
            .collect();
        self.header.map = map_section::resolve(&entries)?;
        Ok(())
    }

    /// Reads a referenced file: from the files in memory where there are some (the one
    /// named as the reference's path beside the referencing file, else as written, else
    /// the one of the same last path component), else from disk.
    fn read_reference(&mut self, from: &Path, name: &Path, level: usize) -> Result<PathBuf> {
        let Some(files) = self.files else {
            let target = resolve_reference(from, name);
            self.read_file(&target, level)?;
            return Ok(target);
        };
        let beside = lexical(&from.parent().unwrap_or(Path::new("")).join(name));
        let last = |p: &Path| p.file_name().map(|n| n.to_os_string());
        let found = files
            .iter()
            .find(|(n, _)| lexical(Path::new(n)) == beside)
            .or_else(|| files.iter().find(|(n, _)| lexical(Path::new(n)) == lexical(name)))
            .or_else(|| files.iter().find(|(n, _)| last(Path::new(n)) == last(name)));
        let Some((found, bytes)) = found else {
            return Err(Error::reading(&beside, std::io::Error::from(std::io::ErrorKind::NotFound)));
        };
        let target = PathBuf::from(found);
        self.read_held(&target, Some(FileBytes::Owned(bytes.clone())), level)?;
        Ok(target)
    }

    fn read_file(&mut self, path: &Path, level: usize) -> Result<()> {
        self.read_held(path, None, level)
    }

    /// Reads the file `path` (its bytes `held` when they are at hand, else from disk).
    fn read_held(&mut self, path: &Path, held: Option<FileBytes>, level: usize) -> Result<()> {
        let canonical = match held {
            None => path.canonicalize().unwrap_or_else(|_| path.to_path_buf()),
            Some(_) => lexical(path),
        };
        if self.stack.contains(&canonical) {
            return Err(Error::format(path, Location::File, "$ROAD_CRG_FILE", "file references form a loop"));
        }
        if level > MAX_REFERENCE_DEPTH {
            return Err(Error::format(
                path,
                Location::File,
                "$ROAD_CRG_FILE",
                format!("file references nest deeper than {MAX_REFERENCE_DEPTH} levels"),
            ));
        }
        let bytes = match held {
            Some(bytes) => bytes,
            None => open(path)?,
        };
        self.stack.push(canonical);
        let result = self.parse(path, &bytes, level);
        self.stack.pop();
        // A file cut short while its header was read is told as such, not as what the
        // zeros read in its place would look like.
        bytes.check(path)?;
        if let Some(offset) = result? {
            if self.data.is_some() {
                return Err(Error::format(path, Location::File, "data section", "a second data section was found"));
            }
            self.data = Some(DataSource { path: path.to_path_buf(), bytes, offset });
        }
        Ok(())
    }

    /// Parses the header lines; returns the offset of the data section, if any.
    fn parse(&mut self, path: &Path, bytes: &[u8], level: usize) -> Result<Option<usize>> {
        let mut section = Section::None;
        let mut reference = String::new();
        let mut reference_line = 0;
        for line in syntax::Lines::new(bytes) {
            let text = syntax::latin1(line.bytes);
            // In comment and file sections only a '$' in column 1 ends the section; in
            // a file section a '$NAME' that is no section keyword starts a file name
            // with an environment variable.
            let column_one = matches!(section, Section::Comment | Section::File);
            let tag = match syntax::tag(&text) {
                _ if column_one && !text.starts_with('$') => None,
                Some(Tag::End) if section == Section::File && starts_with_variable(&text) => None,
                t => t,
            };
            if let Some(tag) = tag {
                if section == Section::File {
                    self.follow_reference(path, &std::mem::take(&mut reference), reference_line, level)?;
                }
                section = Section::None;
                match tag {
                    Tag::Data => return Ok(Some(line.end)),
                    Tag::End => {
                        if let Some(word) = unknown_section_word(&text) {
                            self.header.warnings.push(format!(
                                "{}:{}: unknown section keyword '{word}': the lines up to the next section are ignored",
                                path.display(),
                                line.number
                            ));
                        }
                    }
                    Tag::Start(s) => {
                        section = s;
                        self.start_section(s, level);
                    }
                }
                continue;
            }
            match section {
                Section::Comment => self.header.comments.push(text),
                _ if syntax::is_comment(&text) => {}
                Section::File => {
                    reference_line = line.number;
                    reference.push_str(&reference_piece(&text));
                }
                Section::Road => self.road_line(path, line.number, &text, level)?,
                Section::Options | Section::Modifiers => self.setting_line(section, path, line.number, &text, level)?,
                Section::Mpro => {
                    if let Some((k, v)) = key_value(&text) {
                        if !map_section::is_keyword(&k) {
                            self.header.warnings.push(format!(
                                "{}:{}: $ROAD_CRG_MPRO: unknown keyword '{}' kept but not used",
                                path.display(),
                                line.number,
                                k.to_ascii_uppercase()
                            ));
                        }
                        self.header.mpro.push((k, syntax::strip_inline_comment(v).trim().to_string()));
                        self.mpro_places.push((path.to_path_buf(), line.number));
                    }
                }
                Section::DataDef => self.data_def_line(path, line.number, &text, level)?,
                Section::None => {}
            }
        }
        if section == Section::File {
            self.follow_reference(path, &reference, reference_line, level)?;
        }
        Ok(None)
    }

    fn start_section(&mut self, section: Section, level: usize) {
        match section {
            Section::Options if level == 0 || self.option_level.is_none() => {
                self.header.options.reset_options();
                self.option_level = Some(level);
            }
            Section::Modifiers if level == 0 || self.modifier_level.is_none() => {
                self.header.modifiers.clear();
                self.header.modifiers_given = true;
                self.modifier_level = Some(level);
            }
            _ => {}
        }
    }

    fn follow_reference(&mut self, from: &Path, name: &str, line: usize, level: usize) -> Result<()> {
        if name.is_empty() {
            return Err(Error::format(from, Location::Line(line), "$ROAD_CRG_FILE", "names no file"));
        }
        let expanded = expand_variables(name).map_err(|var| {
            Error::format(
                from,
                Location::Line(line),
                "$ROAD_CRG_FILE",
                format!("environment variable ${var} is not set"),
            )
        })?;
        let target = self.read_reference(from, Path::new(&expanded), level + 1)?;
        self.header.references.push(target);
        Ok(())
    }

    fn road_line(&mut self, path: &Path, number: usize, text: &str, level: usize) -> Result<()> {
        let Some((key, value)) = key_value(text) else {
            self.header.warnings.push(format!("{}:{number}: $ROAD_CRG: ignoring line without '='", path.display()));
            return Ok(());
        };
        let field = key.to_ascii_uppercase();
        let v = finite_value(path, number, &field, value)?;
        if let Some(i) = OFFSET_KEYS.iter().position(|k| k.eq_ignore_ascii_case(&key)) {
            self.header.road.offset[i] = Some(v);
            return Ok(());
        }
        match lookup(&ROAD_KEYS, &key) {
            None if !WGS84_KEYS.contains(&key.as_str()) => {
                self.header
                    .warnings
                    .push(format!("{}:{number}: $ROAD_CRG: unknown keyword '{field}' ignored", path.display()));
                self.header.road.extra.push((field, v));
            }
            Some((_, k)) => {
                *self.header.road.slot(k) = Some(v);
                if level == 0 {
                    let given = &mut self.header.road.top_file_gives;
                    match k {
                        RoadKey::EndX => given.x_end = true,
                        RoadKey::EndY => given.y_end = true,
                        RoadKey::StartZ => given.z_start = true,
                        RoadKey::EndZ => given.z_end = true,
                        _ => {}
                    }
                }
            }
            None => self.header.road.extra.push((field, v)),
        }
        Ok(())
    }

    /// A line of `$ROAD_CRG_OPTS` or `$ROAD_CRG_MODS`. Only the top file, or the first
    /// referenced file that has the section, sets them.
    fn setting_line(&mut self, section: Section, path: &Path, number: usize, text: &str, level: usize) -> Result<()> {
        let (family, claimed, name) = match section {
            Section::Options => (Family::Option, self.option_level, "$ROAD_CRG_OPTS"),
            _ => (Family::Modifier, self.modifier_level, "$ROAD_CRG_MODS"),
        };
        if !(level == 0 || claimed == Some(level)) {
            return Ok(());
        }
        let Some((key, value)) = key_value(text) else { return Ok(()) };
        let field = key.to_ascii_uppercase();
        let at = format!("{}:{number}: {field}", path.display());
        // The map checks' tolerances (unknown to the reference, which warns of them as of any
        // unknown keyword, below); a value that is no positive number leaves the default.
        if family == Family::Option && (key == "check_pro" || key == "check_wgs") {
            if let Some(v) = parse_f64_prefix(value).filter(|v| v.is_finite() && *v > 0.0) {
                let t = &mut self.header.map_tolerances;
                *(if key == "check_pro" { &mut t.projected } else { &mut t.geodesic }) = v;
            }
        }
        let Some(setting) = settings::by_keyword(family, &key) else {
            if family == Family::Option && IGNORED_OPTION_KEYWORDS.iter().any(|k| key.starts_with(k)) {
                return Ok(());
            }
            self.header.warnings.push(format!("{at}: unknown keyword in {name}, ignored"));
            return Ok(());
        };
        let target = match family {
            Family::Option => &mut self.header.options,
            Family::Modifier => &mut self.header.modifiers,
        };
        let id = setting.id;
        let warning = match setting.accepts {
            Accepts::Choice { max } => match parse_i32_prefix(value).filter(|v| (0..=max).contains(v)) {
                Some(v) => target.set_int(id, v).err().map(|e| format!("{at}: {e}")),
                None => Some(format!("{at}: value '{}' is not one of 0..{max}; ignored", value.trim())),
            },
            Accepts::Flag => {
                // The reference sets these checks only for the value 1, and stores the option's id.
                if parse_i32_prefix(value) == Some(1) {
                    target.set_int(id, id as i32)?;
                }
                None
            }
            Accepts::Count => {
                self.header.warn_msgs = parse_i32_prefix(value);
                None
            }
            Accepts::Any | Accepts::Positive => {
                let v = finite_value(path, number, &field, value)?;
                target.set_double(id, v).err().map(|e| format!("{at}: {e}"))
            }
        };
        self.header.warnings.extend(warning);
        Ok(())
    }

    fn data_def_line(&mut self, path: &Path, number: usize, text: &str, level: usize) -> Result<()> {
        let t = text.trim_start_matches(' ');
        if syntax::starts_with_ignore_case(t, "#:") {
            self.header.format = DataFormat::from_letters(&t[2..]).ok_or_else(|| {
                Error::format(
                    path,
                    Location::Line(number),
                    "$KD_Definition",
                    format!("unknown data format '{}' (LRFI, LDFI, KRBI or KDBI)", t[2..].trim()),
                )
            })?;
        } else if syntax::starts_with_ignore_case(t, "D:") {
            let channel = syntax::parse_channel(t)
                .map_err(|e| Error::format(path, Location::Line(number), "$KD_Definition", e))?;
            if level == 0 && matches!(channel, Channel::SectionIndex(_)) {
                self.header.top_file_numbers_sections = true;
            }
            self.header.channels.push(channel);
        } else if !syntax::starts_with_ignore_case(t, "U:") {
            self.header.warnings.push(format!("{}:{number}: $KD_Definition: ignoring line", path.display()));
        }
        Ok(())
    }
}

/// Keys of `$ROAD_CRG` that are kept (and written back) but not used.
const WGS84_KEYS: [&str; 6] = [
    "reference_line_start_lon",
    "reference_line_start_lat",
    "reference_line_start_alt",
    "reference_line_end_lon",
    "reference_line_end_lat",
    "reference_line_end_alt",
];

/// The word of a `$WORD` line that names no section (a typo such as `$ROAD_CGR`); a
/// plain `$` or `$!` comment line ends a section and names nothing.
fn unknown_section_word(line: &str) -> Option<&str> {
    let rest = line.trim_start_matches(' ').strip_prefix('$')?;
    if !rest.starts_with(|c: char| c.is_ascii_alphabetic()) {
        return None;
    }
    rest.split(|c: char| c.is_whitespace() || c == '!').next()
}

/// Whether a line starts with `$` and a variable name (letters, digits, `_`).
fn starts_with_variable(line: &str) -> bool {
    line.strip_prefix('$').and_then(|r| r.chars().next()).is_some_and(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// A header number that must be finite; the error names the line and field.
fn finite_value(path: &Path, number: usize, field: &str, value: &str) -> Result<f64> {
    let at = Location::Line(number);
    match parse_f64_prefix(value) {
        Some(v) if v.is_finite() => Ok(v),
        Some(_) => Err(Error::format(path, at, field, "value must be finite")),
        None => Err(Error::format(path, at, field, format!("'{}' is not a number", value.trim()))),
    }
}

/// The part of a `$ROAD_CRG_FILE` line that belongs to the file name: the first
/// blank-separated word before any `!`.
fn reference_piece(line: &str) -> String {
    syntax::strip_inline_comment(line).split_whitespace().next().unwrap_or("").to_string()
}

/// Replaces `$NAME` (up to the next `/`) by the environment variable's value.
/// Returns the name of an unset variable as the error.
fn expand_variables(name: &str) -> std::result::Result<String, String> {
    let mut out = String::new();
    let mut rest = name;
    while let Some(i) = rest.find('$') {
        out.push_str(&rest[..i]);
        let after = &rest[i + 1..];
        let end = after.find('/').unwrap_or(after.len());
        let var = &after[..end];
        out.push_str(&std::env::var(var).map_err(|_| var.to_string())?);
        rest = &after[end..];
    }
    out.push_str(rest);
    Ok(out)
}

/// A path with `.` dropped and `..` taken back where it can be (`a/b/../c` is `a/c`),
/// without asking the file system.
fn lexical(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for part in path.components() {
        match part {
            std::path::Component::CurDir => {}
            std::path::Component::ParentDir
                if out.components().next_back().is_some_and(|c| matches!(c, std::path::Component::Normal(_))) =>
            {
                out.pop();
            }
            other => out.push(other.as_os_str()),
        }
    }
    out
}

/// A relative reference is looked up in the working folder (as the reference library
/// does) and, when not found there, beside the referencing file.
fn resolve_reference(from: &Path, name: &Path) -> PathBuf {
    if name.is_absolute() || name.exists() {
        return name.to_path_buf();
    }
    match from.parent() {
        Some(dir) if dir.join(name).exists() => dir.join(name),
        _ => name.to_path_buf(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reference_names() {
        assert_eq!(reference_piece("  ../a/b.crg  ! comment"), "../a/b.crg");
        assert_eq!(reference_piece("!only"), "");
        std::env::set_var("OPENCRG_TEST_DIR", "/tmp/x");
        assert_eq!(expand_variables("$OPENCRG_TEST_DIR/r.crg").unwrap(), "/tmp/x/r.crg");
        assert_eq!(expand_variables("$OPENCRG_NOT_SET_123/r.crg").unwrap_err(), "OPENCRG_NOT_SET_123");
    }
}
