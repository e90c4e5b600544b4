//! The classic API's constants, named as in C (`dCrg...`): message levels, option and
//! modifier identifiers (tested against the core's settings table), their values.
#![allow(non_upper_case_globals)]

use std::ffi::{c_int, c_uint};

/// Message level: no messages.
pub const dCrgMsgLevelNone: c_int = 0;
/// Message level: fatal errors.
pub const dCrgMsgLevelFatal: c_int = 1;
/// Message level: warnings.
pub const dCrgMsgLevelWarn: c_int = 2;
/// Message level: notices (the default).
pub const dCrgMsgLevelNotice: c_int = 3;
/// Message level: information.
pub const dCrgMsgLevelInfo: c_int = 4;
/// Message level: debugging.
pub const dCrgMsgLevelDebug: c_int = 5;

/// Option: border mode in u [integer, dCrgBorderMode*].
pub const dCrgCpOptionBorderModeU: c_uint = 1;
/// Option: border mode in v [integer, dCrgBorderMode*].
pub const dCrgCpOptionBorderModeV: c_uint = 2;
/// Option: curvature mode [integer, dCrgCurv*].
pub const dCrgCpOptionCurvMode: c_uint = 3;
/// Option: z offset beyond the u borders [double, m].
pub const dCrgCpOptionBorderOffsetU: c_uint = 5;
/// Option: z offset beyond the v borders [double, m].
pub const dCrgCpOptionBorderOffsetV: c_uint = 6;
/// Option: smoothing zone at the begin [double, m].
pub const dCrgCpOptionSmoothUBegin: c_uint = 7;
/// Option: smoothing zone at the end [double, m].
pub const dCrgCpOptionSmoothUEnd: c_uint = 8;
/// Option: preload the search history at this u [double, m].
pub const dCrgCpOptionRefLineSearchU: c_uint = 9;
/// Option: preload the search history at this u fraction [double, -].
pub const dCrgCpOptionRefLineSearchUFrac: c_uint = 10;
/// Option: close criterion of the search history [double, m].
pub const dCrgCpOptionRefLineClose: c_uint = 11;
/// Option: far criterion of the search history [double, m].
pub const dCrgCpOptionRefLineFar: c_uint = 12;
/// Option: reference line continuation [integer, dCrgRefLine*].
pub const dCrgCpOptionRefLineContinue: c_uint = 13;
/// Option: maximum number of warning messages (integer).
pub const dCrgCpOptionWarnMsgs: c_uint = 14;
/// Option: expected minimum accuracy [double, m].
pub const dCrgCpOptionCheckEps: c_uint = 15;
/// Option: expected minimum increment [double, m].
pub const dCrgCpOptionCheckInc: c_uint = 16;
/// Option: expected absolute tolerance [double, m].
pub const dCrgCpOptionCheckTol: c_uint = 17;
/// Option: local curvature check (integer).
pub const dCrgCpOptionWarnCurvLocal: c_uint = 18;
/// Option: global curvature check (integer).
pub const dCrgCpOptionWarnCurvGlobal: c_uint = 19;

/// Border mode: refuse the evaluation.
pub const dCrgBorderModeNone: c_int = 0;
/// Border mode: z is zero.
pub const dCrgBorderModeExZero: c_int = 1;
/// Border mode: keep the last value (default).
pub const dCrgBorderModeExKeep: c_int = 2;
/// Border mode: repeat the data.
pub const dCrgBorderModeRepeat: c_int = 3;
/// Border mode: reflect the data.
pub const dCrgBorderModeReflect: c_int = 4;

/// Reference line continuation: extrapolate (default).
pub const dCrgRefLineExtrapolate: c_int = 0;
/// Reference line continuation: close the track.
pub const dCrgRefLineCloseTrack: c_int = 1;

/// Curvature mode: curvature of the parallel at v (default).
pub const dCrgCurvLateral: c_int = 0;
/// Curvature mode: curvature of the reference line.
pub const dCrgCurvRefLine: c_int = 1;

/// Modifier: scale factor of the elevation grid (double).
pub const dCrgModScaleZ: c_uint = 21;
/// Modifier: scale factor of the slope (double).
pub const dCrgModScaleSlope: c_uint = 22;
/// Modifier: scale factor of the banking (double).
pub const dCrgModScaleBank: c_uint = 23;
/// Modifier: scale factor of the length (double).
pub const dCrgModScaleLength: c_uint = 24;
/// Modifier: scale factor of the width (double).
pub const dCrgModScaleWidth: c_uint = 25;
/// Modifier: scale factor of the reference line curvature (double).
pub const dCrgModScaleCurvature: c_uint = 26;
/// Modifier: NaN handling of the grid [integer, dCrgGridNaN*].
pub const dCrgModGridNaNMode: c_uint = 27;
/// Modifier: offset of former NaN values [double, m].
pub const dCrgModGridNaNOffset: c_uint = 28;
/// Modifier: reference point v [double, m].
pub const dCrgModRefPointV: c_uint = 29;
/// Modifier: reference point v fraction (double).
pub const dCrgModRefPointVFrac: c_uint = 30;
/// Modifier: reference point v offset [double, m].
pub const dCrgModRefPointVOffset: c_uint = 31;
/// Modifier: reference point u [double, m].
pub const dCrgModRefPointU: c_uint = 32;
/// Modifier: reference point u fraction (double).
pub const dCrgModRefPointUFrac: c_uint = 33;
/// Modifier: reference point u offset [double, m].
pub const dCrgModRefPointUOffset: c_uint = 34;
/// Modifier: target x of the reference point [double, m].
pub const dCrgModRefPointX: c_uint = 35;
/// Modifier: target y of the reference point [double, m].
pub const dCrgModRefPointY: c_uint = 36;
/// Modifier: target z of the reference point [double, m].
pub const dCrgModRefPointZ: c_uint = 37;
/// Modifier: target heading of the reference point [double, rad].
pub const dCrgModRefPointPhi: c_uint = 38;
/// Modifier: reference line offset x [double, m].
pub const dCrgModRefLineOffsetX: c_uint = 39;
/// Modifier: reference line offset y [double, m].
pub const dCrgModRefLineOffsetY: c_uint = 40;
/// Modifier: reference line offset z [double, m].
pub const dCrgModRefLineOffsetZ: c_uint = 41;
/// Modifier: reference line rotation [double, rad].
pub const dCrgModRefLineOffsetPhi: c_uint = 42;
/// Modifier: rotation center x [double, m].
pub const dCrgModRefLineRotCenterX: c_uint = 43;
/// Modifier: rotation center y [double, m].
pub const dCrgModRefLineRotCenterY: c_uint = 44;

/// Size of the option and modifier tables.
pub const dCrgSizeOptList: c_int = 50;

/// NaN mode: keep NaNs.
pub const dCrgGridNaNKeep: c_int = 0;
/// NaN mode: replace NaNs by zero.
pub const dCrgGridNaNSetZero: c_int = 1;
/// NaN mode: replace NaNs by the last valid value (default).
pub const dCrgGridNaNKeepLast: c_int = 2;

/// Orientation: forward.
pub const dCrgOrientFwd: c_int = 0;
/// Orientation: reverse.
pub const dCrgOrientRev: c_int = 1;

/// Data format for `crgDataSetWrite`: LRFI (text, 10-character fields).
pub const dCrgFormatLRFI: c_int = 1;
/// Data format for `crgDataSetWrite`: LDFI (text, 20-character fields).
pub const dCrgFormatLDFI: c_int = 2;
/// Data format for `crgDataSetWrite`: KRBI (binary, 4-byte floats).
pub const dCrgFormatKRBI: c_int = 3;
/// Data format for `crgDataSetWrite`: KDBI (binary, 8-byte doubles).
pub const dCrgFormatKDBI: c_int = 4;
