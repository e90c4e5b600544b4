//! `opencrg fmu`: a CRG file or an OpenDRIVE map packed as an FMU, with the binaries of
//! every platform at hand.

use crate::files::Failure;
use opencrg_fmu::Fmi;
use opencrg_tools::fmu::{binaries_in, write_fmu, Binary, FmuOptions, Platform};
use std::path::{Path, PathBuf};

/// The arguments of `opencrg fmu`.
#[derive(clap::Args)]
pub(crate) struct FmuArgs {
    /// The road: a CRG file, or an OpenDRIVE map (.xodr) with the CRG files its records name.
    road: PathBuf,
    /// The FMU to write (.fmu).
    output: PathBuf,
    /// How many wheels it answers for (1 to 999).
    #[arg(long, default_value_t = 4)]
    wheels: u32,
    /// The FMI version: 2 (2.0) or 3 (3.0).
    #[arg(long, default_value_t = 2)]
    fmi: u32,
    /// A folder of FMU binaries laid out as PLATFORM/FILE (x86_64-linux/libopencrg_fmi.so,
    /// x86_64-windows/opencrg_fmi.dll, aarch64-linux/libopencrg_fmi.so); default:
    /// $OPENCRG_FMU_BINARIES, the release archive's lib/opencrg/fmu, or the development
    /// build's binary beside this program.
    #[arg(long)]
    binaries: Option<PathBuf>,
    /// Leave the CRG file outside the FMU, named by its absolute path (a road of gigabytes
    /// is read in place where it lies; the parameter roadFile names another file).
    #[arg(long)]
    road_outside: bool,
}

/// The binaries to pack: from the folder named, else the first place that has some.
fn binaries(named: Option<&Path>) -> Result<Vec<Binary>, Failure> {
    if let Some(folder) = named {
        let found = binaries_in(folder);
        if found.is_empty() {
            return Err(format!(
                "--binaries {}: no FMU binary there (PLATFORM/FILE, as x86_64-linux/libopencrg_fmi.so)",
                folder.display()
            ));
        }
        return Ok(found);
    }
    if let Some(folder) = std::env::var_os("OPENCRG_FMU_BINARIES") {
        let found = binaries_in(Path::new(&folder));
        if found.is_empty() {
            return Err(format!("OPENCRG_FMU_BINARIES={}: no FMU binary there", Path::new(&folder).display()));
        }
        return Ok(found);
    }
    let exe = std::env::current_exe().map_err(|e| format!("where this program is: {e}"))?;
    let dir = exe.parent().unwrap_or(Path::new("."));
    let found = binaries_in(&dir.join("../lib/opencrg/fmu"));
    if !found.is_empty() {
        return Ok(found);
    }
    match Platform::this() {
        Some(platform) if dir.join(platform.built_name()).is_file() => {
            Ok(vec![Binary { platform, file: dir.join(platform.built_name()) }])
        }
        _ => Err(format!(
            "no FMU binary found beside {} nor in its ../lib/opencrg/fmu: build it (cargo build --release -p opencrg-fmi) \
             or name a folder with --binaries",
            exe.display()
        )),
    }
}

/// Runs `opencrg fmu`.
pub(crate) fn run(args: FmuArgs) -> Result<(), Failure> {
    let fmi = match args.fmi {
        2 => Fmi::V2,
        3 => Fmi::V3,
        other => return Err(format!("--fmi {other}: 2 (FMI 2.0) or 3 (FMI 3.0)")),
    };
    let options = FmuOptions {
        wheels: args.wheels,
        fmi,
        binaries: binaries(args.binaries.as_deref())?,
        outside: args.road_outside,
    };
    let report = write_fmu(&args.road, &args.output, &options).map_err(|e| e.to_string())?;
    let platforms: Vec<&str> = report.platforms.iter().map(|p| p.tuple()).collect();
    eprintln!(
        "{}: FMI {}.0, model exchange and co-simulation, {}, {} variables, model identifier {}, binaries for {}",
        args.output.display(),
        fmi.major(),
        opencrg_core::units::Count(args.wheels as usize, "wheel"),
        report.variables,
        report.identifier,
        platforms.join(", ")
    );
    Ok(())
}
