//! The FMU's variables: what each wheel reads and answers, the parameters, their value
//! references, types, units and start values. The model description and the FMI
//! binding both take them from here.
//!
//! Value references: the parameters below 100; wheel `i` (1-based) quantity `q` at
//! `100 * i + q`, so a reference names its wheel and quantity without a table.

use opencrg_core::settings::{self, opt, Kind as SettingKind, Value};

/// What an FMU carries: one CRG file, or an OpenDRIVE map with the CRG files its records
/// name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A CRG file.
    Crg,
    /// An OpenDRIVE map.
    Map,
}

/// The FMI type of a variable (FMI 2 names; FMI 3 writes `Float64`, `Int32`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Type {
    /// A double.
    Real,
    /// A 32-bit integer.
    Integer,
    /// An integer naming one of a list of items (FMI 2 reads it as an Integer, FMI 3 as
    /// an Int64): a map's road, each item named by its OpenDRIVE id.
    Enumeration,
    /// A Boolean.
    Boolean,
    /// A string.
    String,
}

/// What a variable is to the importer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Causality {
    /// Set by the importer, read by the FMU.
    Input,
    /// Computed by the FMU.
    Output,
    /// Set before the simulation (or between steps, where tunable).
    Parameter,
    /// The simulation time (FMI 3 only).
    Independent,
    /// Computed by the FMU for its own ends: the event indicators of model exchange.
    Local,
}

/// How a variable may change.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Variability {
    /// At any time.
    Continuous,
    /// At events only (model exchange: the event indicators announce them).
    Discrete,
    /// Only before the simulation.
    Fixed,
    /// Between steps and at events.
    Tunable,
}

/// A value of any variable type.
#[derive(Debug, Clone, PartialEq)]
pub enum Start {
    /// A double.
    Real(f64),
    /// An integer.
    Integer(i32),
    /// A Boolean.
    Boolean(bool),
    /// A string.
    String(String),
}

/// One quantity of a wheel; its value reference is `100 * wheel + quantity as u32`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// Input: the wheel's x.
    X = 0,
    /// Input: the wheel's y.
    Y = 1,
    /// The surface's height.
    Z = 2,
    /// The friction coefficient.
    Friction = 3,
    /// The upward unit normal's x component.
    Nx = 4,
    /// Its y component.
    Ny = 5,
    /// Its z component.
    Nz = 6,
    /// Whether the wheel is on the road (see the guide for what holds off it).
    OnRoad = 7,
    /// A map's s along the road.
    S = 8,
    /// A map's t across it.
    T = 9,
    /// A map's road: its index in the file's order, from 0.
    Road = 10,
    /// A map's lane id.
    Lane = 11,
    /// A CRG file's u.
    U = 12,
    /// A CRG file's v.
    V = 13,
    /// A CRG file's heading at (u, v).
    Heading = 14,
    /// A CRG file's curvature at (u, v).
    Curvature = 15,
    /// Model exchange's event indicator: 1 while the wheel's on the road, road and lane
    /// are those of the last event, -1 once one of them differs.
    EventIndicator = 16,
}

/// Everything about one wheel quantity.
struct QuantityInfo {
    quantity: Quantity,
    name: &'static str,
    ty: Type,
    unit: Option<&'static str>,
    /// `None`: of both kinds.
    only: Option<Kind>,
    description: &'static str,
}

const fn q(
    quantity: Quantity,
    name: &'static str,
    ty: Type,
    unit: Option<&'static str>,
    only: Option<Kind>,
    description: &'static str,
) -> QuantityInfo {
    QuantityInfo { quantity, name, ty, unit, only, description }
}

const M: Option<&str> = Some("m");

/// Every wheel quantity, in value reference order.
#[rustfmt::skip]
const QUANTITIES: [QuantityInfo; 17] = [
    q(Quantity::X, "x", Type::Real, M, None, "x of the wheel's contact point, in the road's frame"),
    q(Quantity::Y, "y", Type::Real, M, None, "y of the wheel's contact point, in the road's frame"),
    q(Quantity::Z, "z", Type::Real, M, None, "height of the road surface under the wheel"),
    q(Quantity::Friction, "friction", Type::Real, None, None, "friction coefficient of the surface under the wheel"),
    q(Quantity::Nx, "nx", Type::Real, None, None, "x component of the surface's upward unit normal"),
    q(Quantity::Ny, "ny", Type::Real, None, None, "y component of the surface's upward unit normal"),
    q(Quantity::Nz, "nz", Type::Real, None, None, "z component of the surface's upward unit normal"),
    q(Quantity::OnRoad, "onRoad", Type::Boolean, None, None, "whether the wheel is on the road (off it the other outputs hold their documented values)"),
    q(Quantity::S, "s", Type::Real, M, Some(Kind::Map), "s along the road under the wheel"),
    q(Quantity::T, "t", Type::Real, M, Some(Kind::Map), "t across the road under the wheel"),
    q(Quantity::Road, "road", Type::Enumeration, None, Some(Kind::Map), "the road under the wheel: its index in the map file's order, from 0, an item named by the road's OpenDRIVE id (-1 off every road)"),
    q(Quantity::Lane, "lane", Type::Integer, None, Some(Kind::Map), "the OpenDRIVE lane id under the wheel (0 off every road)"),
    q(Quantity::U, "u", Type::Real, M, Some(Kind::Crg), "u along the CRG reference line under the wheel"),
    q(Quantity::V, "v", Type::Real, M, Some(Kind::Crg), "v across the CRG reference line under the wheel"),
    q(Quantity::Heading, "heading", Type::Real, Some("rad"), Some(Kind::Crg), "heading of the CRG reference line at the wheel's u"),
    q(Quantity::Curvature, "curvature", Type::Real, Some("1/m"), Some(Kind::Crg), "curvature at the wheel's (u, v)"),
    q(Quantity::EventIndicator, "eventIndicator", Type::Real, None, None, "model exchange's event indicator: 1 while onRoad, road and lane are those of the last event, -1 once one of them differs"),
];

impl Quantity {
    /// The quantity at offset `k` of a wheel's value references.
    pub fn from_offset(k: u32) -> Option<Quantity> {
        QUANTITIES.get(k as usize).map(|i| i.quantity)
    }

    /// Whether an FMU of `kind` has it.
    pub fn of(self, kind: Kind) -> bool {
        QUANTITIES[self as usize].only.is_none_or(|k| k == kind)
    }

    /// Its FMI type.
    pub fn ty(self) -> Type {
        QUANTITIES[self as usize].ty
    }

    /// Its name after `wheel[i].`.
    pub fn name(self) -> &'static str {
        QUANTITIES[self as usize].name
    }

    /// Whether the importer sets it.
    pub fn is_input(self) -> bool {
        matches!(self, Quantity::X | Quantity::Y)
    }
}

/// Value references per wheel.
pub const WHEEL_STRIDE: u32 = 100;

/// The most wheels an FMU answers for (value references stay below 100 000).
pub const MAX_WHEELS: u32 = 999;

/// The value reference of the simulation time (FMI 3).
pub const TIME: u32 = 0;

/// A parameter of the FMU.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Parameter {
    /// The friction answered where the road gives none (tunable).
    FrictionDefault,
    /// The behaviour profile a CRG file is read and evaluated with (a CRG file's FMU only).
    Compat,
    /// A CRG file to read instead of the FMU's own road (a CRG file's FMU only): empty for
    /// the road the FMU was made with (for a road left outside the FMU, its path).
    RoadFile,
    /// A contact point option of the C API (a CRG file's FMU only), by identifier.
    Option(u32),
}

/// The contact point options a CRG file's FMU offers as parameters (named by the
/// settings table's code name: the `$ROAD_CRG_OPTS` keyword, or for the curvature mode,
/// which has none, the C constant's).
const OPTIONS: [u32; 8] = [
    opt::BORDER_MODE_U,
    opt::BORDER_MODE_V,
    opt::BORDER_OFFSET_U,
    opt::BORDER_OFFSET_V,
    opt::SMOOTH_U_BEGIN,
    opt::SMOOTH_U_END,
    opt::REFLINE_CONTINUE,
    opt::CURV_MODE,
];

/// The friction answered where the road gives none, unless the parameter says otherwise.
pub const FRICTION_DEFAULT: f64 = 1.0;

/// The behaviour profile's start value.
pub const COMPAT_DEFAULT: &str = "current";

impl Parameter {
    /// Every parameter of an FMU of `kind`, in value reference order.
    pub fn all(kind: Kind) -> Vec<Parameter> {
        let mut all = vec![Parameter::FrictionDefault];
        if kind == Kind::Crg {
            all.push(Parameter::Compat);
            all.push(Parameter::RoadFile);
            let mut ids = OPTIONS.to_vec();
            ids.sort_unstable();
            all.extend(ids.into_iter().map(Parameter::Option));
        }
        all
    }

    /// Its value reference.
    pub fn vr(self) -> u32 {
        match self {
            Parameter::FrictionDefault => 1,
            Parameter::Compat => 2,
            Parameter::RoadFile => 3,
            Parameter::Option(id) => 10 + id,
        }
    }

    /// The parameter of an FMU of `kind` with value reference `vr`.
    pub fn from_vr(kind: Kind, vr: u32) -> Option<Parameter> {
        Parameter::all(kind).into_iter().find(|p| p.vr() == vr)
    }

    /// Its name.
    pub fn name(self) -> String {
        match self {
            Parameter::FrictionDefault => "frictionDefault".into(),
            Parameter::Compat => "compat".into(),
            Parameter::RoadFile => "roadFile".into(),
            Parameter::Option(id) => {
                let name = settings::info(id).map_or_else(|| "unknown".into(), |s| s.code_name());
                format!("options.{name}")
            }
        }
    }

    /// Its FMI type.
    pub fn ty(self) -> Type {
        match self {
            Parameter::FrictionDefault => Type::Real,
            Parameter::Compat | Parameter::RoadFile => Type::String,
            Parameter::Option(id) => match settings::describe(id) {
                Some((_, SettingKind::Int)) => Type::Integer,
                _ => Type::Real,
            },
        }
    }

    /// Whether it may change after initialization.
    pub fn variability(self) -> Variability {
        match self {
            Parameter::FrictionDefault => Variability::Tunable,
            _ => Variability::Fixed,
        }
    }

    fn description(self) -> String {
        match self {
            Parameter::FrictionDefault => "friction answered where the road gives none (and off every road)".into(),
            Parameter::Compat => "behaviour profile: current, or 2.0.1 for the releases 2.0.1 and 1.2.0".into(),
            Parameter::RoadFile => "a CRG file (its path) read instead of the FMU's road; empty: the FMU's own road \
                                    (a road of gigabytes is read in place from its file)"
                .into(),
            Parameter::Option(id) => {
                format!(
                    "contact point option {} ({}); applied where changed",
                    settings::name(id),
                    settings::info(id).map_or("", |s| s.c_constant)
                )
            }
        }
    }
}

/// A contact point option's value when the road sets none: the value that behaves as
/// unset (no offset, no smoothing, extrapolation, lateral curvature).
pub(crate) fn unset_value(id: u32) -> Value {
    match settings::describe(id) {
        Some((_, SettingKind::Int)) => Value::Int(0),
        _ => Value::Double(0.0),
    }
}

/// One variable as the model description lists it.
#[derive(Debug, Clone, PartialEq)]
pub struct Variable {
    /// Its name (structured naming: `wheel[1].z`).
    pub name: String,
    /// Its value reference.
    pub vr: u32,
    /// Its type.
    pub ty: Type,
    /// Input, output, parameter or the time.
    pub causality: Causality,
    /// How it may change.
    pub variability: Variability,
    /// Its unit, one of [`UNITS`].
    pub unit: Option<&'static str>,
    /// What it is.
    pub description: String,
    /// Its start value (inputs and parameters).
    pub start: Option<Start>,
    /// The value references of the inputs an output depends on.
    pub depends_on: Vec<u32>,
}

/// The units the variables use, with their SI base unit exponents (m, rad).
pub const UNITS: [(&str, i32, i32); 3] = [("m", 1, 0), ("rad", 0, 1), ("1/m", -1, 0)];

/// The value reference of wheel `wheel` (1-based) quantity `quantity`.
pub fn wheel_vr(wheel: u32, quantity: Quantity) -> u32 {
    WHEEL_STRIDE * wheel + quantity as u32
}

/// The wheel (1-based) and quantity a value reference names in an FMU of `kind` with
/// `wheels` wheels.
pub fn wheel_of(kind: Kind, wheels: u32, vr: u32) -> Option<(u32, Quantity)> {
    let (wheel, k) = (vr / WHEEL_STRIDE, vr % WHEEL_STRIDE);
    let quantity = Quantity::from_offset(k)?;
    (1..=wheels).contains(&wheel).then_some(())?;
    quantity.of(kind).then_some((wheel, quantity))
}

/// Every variable of an FMU of `kind` with `wheels` wheels, in value reference order
/// (FMI 3's time first when `with_time`): the wheels start at `start`, the parameters
/// at `parameter_start`.
pub fn variables(
    kind: Kind,
    wheels: u32,
    with_time: bool,
    start: (f64, f64),
    parameter_start: impl Fn(Parameter) -> Start,
) -> Vec<Variable> {
    let mut out = Vec::new();
    if with_time {
        out.push(Variable {
            name: "time".into(),
            vr: TIME,
            ty: Type::Real,
            causality: Causality::Independent,
            variability: Variability::Continuous,
            unit: None,
            description: "simulation time".into(),
            start: None,
            depends_on: Vec::new(),
        });
    }
    for p in Parameter::all(kind) {
        out.push(Variable {
            name: p.name(),
            vr: p.vr(),
            ty: p.ty(),
            causality: Causality::Parameter,
            variability: p.variability(),
            unit: None,
            description: p.description(),
            start: Some(parameter_start(p)),
            depends_on: Vec::new(),
        });
    }
    let (x0, y0) = start;
    for wheel in 1..=wheels {
        let inputs = vec![wheel_vr(wheel, Quantity::X), wheel_vr(wheel, Quantity::Y)];
        for info in QUANTITIES.iter().filter(|i| i.quantity.of(kind)) {
            let quantity = info.quantity;
            let input = quantity.is_input();
            let causality = match quantity {
                _ if input => Causality::Input,
                Quantity::EventIndicator => Causality::Local,
                _ => Causality::Output,
            };
            out.push(Variable {
                name: format!("wheel[{wheel}].{}", info.name),
                vr: wheel_vr(wheel, quantity),
                ty: info.ty,
                causality,
                variability: if info.ty == Type::Real { Variability::Continuous } else { Variability::Discrete },
                unit: info.unit,
                description: info.description.into(),
                start: match quantity {
                    Quantity::X => Some(Start::Real(x0)),
                    Quantity::Y => Some(Start::Real(y0)),
                    _ => None,
                },
                depends_on: if input { Vec::new() } else { inputs.clone() },
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn value_references_name_their_wheel_and_quantity() {
        assert_eq!(wheel_vr(3, Quantity::Nz), 306);
        assert_eq!(wheel_of(Kind::Crg, 4, 306), Some((3, Quantity::Nz)));
        assert_eq!(wheel_of(Kind::Crg, 4, 512), None, "a fifth wheel");
        assert_eq!(wheel_of(Kind::Crg, 4, 108), None, "s is a map's");
        assert_eq!(wheel_of(Kind::Map, 4, 108), Some((1, Quantity::S)));
        assert_eq!(wheel_of(Kind::Map, 4, 112), None, "u is a CRG file's");
        assert_eq!(wheel_of(Kind::Map, 4, 16), None, "a parameter's range");
        assert_eq!(wheel_of(Kind::Map, 4, 117), None, "no quantity 17");
        for (k, info) in QUANTITIES.iter().enumerate() {
            assert_eq!(info.quantity as usize, k, "{}", info.name);
        }
    }

    #[test]
    fn parameters_have_distinct_references_below_the_wheels() {
        let all = Parameter::all(Kind::Crg);
        let mut vrs: Vec<u32> = all.iter().map(|p| p.vr()).collect();
        vrs.dedup();
        assert_eq!(vrs.len(), all.len());
        assert!(vrs.iter().all(|&v| v != TIME && v < WHEEL_STRIDE), "{vrs:?}");
        assert!(vrs.windows(2).all(|w| w[0] < w[1]), "in order: {vrs:?}");
        for p in all {
            assert_eq!(Parameter::from_vr(Kind::Crg, p.vr()), Some(p));
        }
        assert_eq!(Parameter::from_vr(Kind::Map, Parameter::Option(opt::BORDER_MODE_U).vr()), None);
        assert_eq!(Parameter::Option(opt::BORDER_MODE_U).ty(), Type::Integer);
        assert_eq!(Parameter::Option(opt::BORDER_OFFSET_V).ty(), Type::Real);
        assert_eq!(Parameter::Option(opt::SMOOTH_U_END).name(), "options.BORDER_SMOOTH_UEND");
        assert_eq!(Parameter::Option(opt::CURV_MODE).name(), "options.CURV_MODE");
        assert_eq!(Parameter::Option(opt::REFLINE_CONTINUE).name(), "options.REFLINE_CONTINUATION");
    }
}
