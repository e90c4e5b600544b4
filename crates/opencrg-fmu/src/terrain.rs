//! The road an FMU answers for, loaded, and the answers under each wheel.
//!
//! A CRG file answers as the C API does after `crgLoaderReadFile`, `crgCheck` and
//! `crgDataSetModifiersApply`: (u, v) from the x/y search, z at that (u, v) as
//! `crgEvalxy2z` gives it, heading and curvature as `crgEvaluv2pk`, the normal from the
//! interpolation's gradient. A map answers as a [`Probe`] of the wheel's own that meets
//! each new position of the wheel once (as `opencrg odr eval` answers the wheel's
//! positions in turn), the normal from a second probe of its own.
//! Each wheel's answer is computed when an output is read after its position moved, and
//! only the part read (the normal, the heading and curvature are computed when asked).

use crate::variables::{unset_value, Kind, Parameter, Quantity, Start, COMPAT_DEFAULT, FRICTION_DEFAULT};
use opencrg_core::settings::{self, Accepts, Value};
use opencrg_core::{Compat, ContactPoint, Error, Result};
use opencrg_odr::{Map, Probe, Surface};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// A loaded road: a CRG file ready to evaluate, or a map with its CRG files.
#[derive(Clone)]
pub enum Terrain {
    /// A CRG file, checked and its modifiers applied.
    Crg(Arc<opencrg_core::Road>),
    /// A map.
    Map(Arc<Surface>),
}

impl Terrain {
    /// Reads the CRG file in `path` as the C API's programs prepare it: read, checked
    /// (refused where the check fails) and its modifiers applied.
    pub fn load_crg(path: &Path, compat: Compat) -> Result<Terrain> {
        let mut road = opencrg_core::Road::load_with(path, compat)?;
        road.check().map_err(|e| Error::Check(format!("{}: {e}", path.display())))?;
        road.apply_modifiers();
        Ok(Terrain::Crg(Arc::new(road)))
    }

    /// A flat road of four nodes: what an FMU answers on while the CRG file it names
    /// outside itself is missing (it refuses to initialize meanwhile).
    pub fn placeholder() -> Result<Terrain> {
        let road = opencrg_core::synth::RoadSpec::straight(1.0, 1.0, 1.0, 1.0).build()?;
        Ok(Terrain::Crg(Arc::new(road)))
    }

    /// Reads the map in `path` and the CRG files its records name; a record whose file
    /// (as written) is in `moved` reads the path given there instead.
    pub fn load_map(path: &Path, moved: &[(String, PathBuf)]) -> Result<Terrain> {
        let mut map = Map::load(path)?;
        let records = map.roads.iter_mut().flat_map(|r| &mut r.crg);
        for record in records.chain(map.junctions.iter_mut().flat_map(|j| &mut j.crg)) {
            if let Some((_, to)) = moved.iter().find(|(file, _)| *file == record.file) {
                record.path = to.clone();
            }
        }
        Ok(Terrain::Map(Arc::new(Surface::new(map)?)))
    }

    /// A CRG file or a map.
    pub fn kind(&self) -> Kind {
        match self {
            Terrain::Crg(_) => Kind::Crg,
            Terrain::Map(_) => Kind::Map,
        }
    }

    /// Where the wheels start: a CRG file's reference line (v = 0, or the nearest v of
    /// the grid) 1 m after its start, a map's first road's reference line 1 m after its
    /// start (each the middle of a shorter road).
    pub fn start_point(&self) -> (f64, f64) {
        match self {
            Terrain::Crg(road) => {
                let ((u0, u1), (v0, v1)) = (road.u_range(), road.v_range());
                let cp = ContactPoint::new(road.clone());
                cp.uv_to_xy(u0 + (0.5 * (u1 - u0)).min(1.0), 0f64.clamp(v0, v1)).unwrap_or((0.0, 0.0))
            }
            Terrain::Map(surface) => match surface.map().roads.first() {
                Some(road) => {
                    let p = road.reference((0.5 * road.length).min(1.0));
                    (p.x, p.y)
                }
                None => (0.0, 0.0),
            },
        }
    }

    /// The start value of a parameter: what the road gives, or what behaves as unset.
    pub fn parameter_start(&self, parameter: Parameter) -> Start {
        match parameter {
            Parameter::FrictionDefault => Start::Real(FRICTION_DEFAULT),
            Parameter::Compat => Start::String(COMPAT_DEFAULT.into()),
            Parameter::RoadFile => Start::String(String::new()),
            Parameter::Option(id) => {
                let value = match self {
                    Terrain::Crg(road) => road.options().get(id),
                    Terrain::Map(_) => None,
                };
                match value.unwrap_or_else(|| unset_value(id)) {
                    Value::Int(i) => Start::Integer(i),
                    Value::Double(d) => Start::Real(d),
                }
            }
        }
    }
}

/// One wheel's answer, as far as it was computed since the wheel last moved.
#[derive(Debug, Clone, Copy, Default)]
struct Answer {
    z: f64,
    /// Friction the road gives (NaN: none).
    friction: f64,
    /// A CRG file's u, v, or a map's s, t.
    a: f64,
    b: f64,
    road: i32,
    lane: i32,
    /// Whether the library answered the height (a CRG file answers beyond its grid too).
    answered: bool,
    /// Whether `a` and `b` were found (a CRG file's search answers where its height may
    /// be refused).
    located: bool,
    normal: Option<[f64; 3]>,
    pk: Option<(f64, f64)>,
}

/// A CRG file's u and v ranges, the grid (on the road within them): first and last u,
/// first and last v; not used on a map.
type Ranges = [f64; 4];

impl Answer {
    /// The answer where there is no place: neither found nor answered.
    fn nowhere() -> Answer {
        Answer { friction: f64::NAN, road: -1, ..Answer::default() }
    }

    /// Found at (`a`, `b`), no height answered (yet).
    #[inline(always)]
    fn located(a: f64, b: f64) -> Answer {
        Answer { located: true, a, b, ..Answer::nowhere() }
    }

    /// A CRG file's answer at the (u, v) its search found, with the height the library
    /// answered there (answered where that height is finite).
    fn of_crg(u: f64, v: f64, z: Result<f64>) -> Answer {
        let mut answer = Answer::located(u, v);
        match z {
            Ok(z) if z.is_finite() => answer.answer_crg(u, v, z),
            _ => {}
        }
        answer
    }

    /// Makes this a CRG file's answer of height `z` (finite) at (u, v), written field by
    /// field (this runs once per wheel and step). The fields a CRG file's answers all
    /// hold alike (no friction, road or lane) are kept: the answer must be one of a CRG
    /// file already (made by one of the functions above).
    #[inline(always)]
    fn answer_crg(&mut self, u: f64, v: f64, z: f64) {
        (self.answered, self.located, self.z, self.a, self.b) = (true, true, z, u, v);
        (self.normal, self.pk) = (None, None);
    }
}

/// The evaluator of one wheel (held in place, one per wheel: no indirection on the
/// hot path, whatever the size difference).
#[allow(clippy::large_enum_variant)]
enum Evaluator {
    Crg(ContactPoint),
    /// A map's probe for the ground, and one for the normal (whose queries around the
    /// wheel would otherwise move the first one's track).
    Map(Probe, Probe),
}

/// One wheel: its evaluator, its answer and the position it is of.
struct Wheel {
    /// The position (x and y's bits) the base answer is of: at first a NaN, whose
    /// answer is the first one's, nowhere.
    of: [u64; 2],
    /// A CRG file's u and v ranges (the grid: on the road within them), kept by each
    /// wheel: nothing an evaluation is given points into [`Wheels`], whose fields the
    /// get path then keeps at hand across it.
    ranges: Ranges,
    evaluator: Evaluator,
    answer: Answer,
    /// Its discrete answers (on the road, road, lane) as of the last event.
    latched: Discrete,
}

/// A wheel's discrete answers: whether it is on the road, the road and the lane.
type Discrete = (bool, i32, i32);

/// The wheels of one FMU instance: their positions and answers.
pub struct Wheels {
    wheels: Vec<Wheel>,
    /// The wheels' positions: every x, then every y (see [`Wheels::input_slot`]).
    at: Vec<f64>,
}

/// What an output holds off the road (see the guide): no height, the normal up, the
/// friction parameter's value, no road or lane.
const UP: [f64; 3] = [0.0, 0.0, 1.0];

impl Wheels {
    /// `count` wheels at `start` on `terrain`, a CRG file's contact points with the
    /// options `changed` (identifier and value; a value that behaves as unset removes
    /// the option). Refused: an option value the C API refuses, named.
    pub fn new(terrain: &Terrain, count: usize, start: (f64, f64), changed: &[(u32, Value)]) -> Result<Wheels> {
        let ranges = match terrain {
            Terrain::Crg(road) => {
                let ((u0, u1), (v0, v1)) = (road.u_range(), road.v_range());
                [u0, u1, v0, v1]
            }
            Terrain::Map(_) => [f64::NAN; 4],
        };
        let mut wheels = Vec::with_capacity(count);
        for _ in 0..count {
            let evaluator = match terrain {
                Terrain::Crg(road) => {
                    let mut cp = ContactPoint::new(road.clone());
                    for &(id, value) in changed {
                        let removes = value == unset_value(id)
                            && settings::info(id).is_some_and(|s| s.accepts == Accepts::Positive);
                        if removes {
                            cp.remove_option(id);
                        } else {
                            // Refused with the message of the C API's setter, which names the option.
                            cp.set_option_value(id, value)?;
                        }
                    }
                    Evaluator::Crg(cp)
                }
                Terrain::Map(surface) => Evaluator::Map(surface.probe(), surface.probe()),
            };
            let of = [f64::NAN.to_bits(); 2];
            wheels.push(Wheel { of, ranges, evaluator, answer: Answer::nowhere(), latched: (false, -1, 0) });
        }
        let at = [vec![start.0; count], vec![start.1; count]].concat();
        Ok(Wheels { wheels, at })
    }

    /// How many wheels.
    pub fn len(&self) -> usize {
        self.wheels.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.wheels.is_empty()
    }

    /// Moves wheel `i` (0-based): sets its x or y (other quantities are not inputs and
    /// are ignored).
    #[inline(always)]
    pub fn set(&mut self, i: usize, quantity: Quantity, value: f64) {
        if let Some(slot) = self.input_slot(i, quantity) {
            self.set_slot(slot, value);
        }
    }

    /// The input slot of wheel `i`'s (0-based) x or y: every x first, then every y. (A
    /// wheel's x and y are not side by side: each is read as the 8 bytes it was written
    /// as, which the processor forwards from its store to the load at once, where one
    /// load of both, which the compiler makes of neighbours, would wait for the two
    /// stores to reach the cache.)
    pub fn input_slot(&self, i: usize, quantity: Quantity) -> Option<usize> {
        let n = self.wheels.len();
        match quantity {
            _ if i >= n => None,
            Quantity::X => Some(i),
            Quantity::Y => Some(n + i),
            _ => None,
        }
    }

    /// Sets the input in `slot` (see [`Wheels::input_slot`]); false where there is no
    /// such slot. An answer is computed anew when its wheel's position differs from the
    /// one it is of.
    #[inline(always)]
    pub fn set_slot(&mut self, slot: usize, value: f64) -> bool {
        match self.at.get_mut(slot) {
            Some(place) => {
                *place = value;
                true
            }
            None => false,
        }
    }

    /// Wheel `i`'s (0-based) x and y.
    fn position(&self, i: usize) -> [f64; 2] {
        [self.at[i], self.at[self.wheels.len() + i]]
    }

    /// Wheel `i` (0-based) with its base answer at its position known.
    fn answered(&mut self, i: usize) -> &mut Wheel {
        let at = self.position(i);
        let wheel = &mut self.wheels[i];
        wheel.base(at);
        wheel
    }

    /// Reads into `out` the Real quantities of the wheels that `decode` gives (wheel,
    /// 0-based, and quantity) for the references `vrs`, up to the first reference it
    /// gives none of this FMU for; answers how many it read. The hot path of an
    /// importer's get: the positions and wheels are cut to one length once, so that a
    /// value costs one bounds check.
    #[inline(always)]
    pub fn read_reals(
        &mut self,
        vrs: &[u32],
        out: &mut [f64],
        friction_default: f64,
        decode: impl Fn(u32) -> Option<(usize, Quantity)>,
    ) -> usize {
        let n = self.wheels.len();
        let (xs, ys) = self.at.split_at(n);
        let (ys, wheels) = (&ys[..n], &mut self.wheels[..n]);
        for (k, (&vr, value)) in vrs.iter().zip(out).enumerate() {
            let Some((i, quantity)) = decode(vr).filter(|&(i, _)| i < n) else {
                return k;
            };
            let wheel = &mut wheels[i];
            wheel.base([xs[i], ys[i]]);
            *value = match quantity {
                Quantity::Z => wheel.answer.z,
                _ => wheel.other(quantity, friction_default),
            };
        }
        vrs.len()
    }

    /// A Real quantity of wheel `i` (0-based): its input, or its answer, computed if the
    /// wheel moved; `friction_default` where the road gives no friction.
    pub fn real(&mut self, i: usize, quantity: Quantity, friction_default: f64) -> f64 {
        self.answered(i).other(quantity, friction_default)
    }

    /// An Integer quantity of wheel `i` (0-based): a map's road and lane.
    #[inline]
    pub fn integer(&mut self, i: usize, quantity: Quantity) -> i32 {
        let wheel = self.answered(i);
        match quantity {
            Quantity::Road => wheel.answer.road,
            Quantity::Lane => wheel.answer.lane,
            _ => 0,
        }
    }

    /// Whether wheel `i` (0-based) is on the road.
    #[inline]
    pub fn on_road(&mut self, i: usize) -> bool {
        self.answered(i).on_road()
    }

    /// Every wheel's discrete answers (on the road, road, lane) as they are now become
    /// those of the last event (model exchange: at initialization and at each event).
    pub fn latch(&mut self) {
        for i in 0..self.wheels.len() {
            let wheel = self.answered(i);
            wheel.latched = wheel.discrete();
        }
    }

    /// Wheel `i`'s (0-based) discrete answers as of the last event.
    pub fn latched(&self, i: usize) -> (bool, i32, i32) {
        self.wheels[i].latched
    }
}

impl Wheel {
    /// Computes the base answer if the wheel moved since: found where the road answers
    /// the height and the wheel is on the road (within a CRG file's grid, on a map's
    /// road); a CRG file's u and v wherever its search answers. Only the check of the
    /// position is inline; [`Wheel::compute`] takes a CRG file's common case (the lean
    /// search and the plain elevation, as `crgEvalxy2z` does) first, every other case in
    /// [`Wheel::base_found`] and [`Wheel::base_otherwise`].
    #[inline(always)]
    fn base(&mut self, at: [f64; 2]) {
        if self.of != at.map(f64::to_bits) {
            self.compute(at[0], at[1]);
        }
    }

    /// The base answer at `at` (see [`Wheel::base`]).
    #[inline(never)]
    fn compute(&mut self, x: f64, y: f64) {
        self.of = [x.to_bits(), y.to_bits()];
        match &mut self.evaluator {
            Evaluator::Crg(cp) => match cp.xy_to_uv_lean(x, y) {
                Some((u, v)) => match cp.uv_to_z_plain(u, v) {
                    Some(z) if z.is_finite() => self.answer.answer_crg(u, v, z),
                    _ => self.base_found(u, v),
                },
                None => self.base_otherwise(x, y),
            },
            Evaluator::Map(..) => self.base_otherwise(x, y),
        }
    }

    /// [`Wheel::base`] of a CRG file whose lean search found (u, v) where the plain
    /// elevation does not apply.
    #[inline(never)]
    fn base_found(&mut self, u: f64, v: f64) {
        if let Evaluator::Crg(cp) = &mut self.evaluator {
            self.answer = Answer::of_crg(u, v, cp.z_of_found(u, v));
        }
    }

    /// [`Wheel::base`] where a CRG file's lean search declined, and on a map.
    #[inline(never)]
    fn base_otherwise(&mut self, x: f64, y: f64) {
        self.answer = match &mut self.evaluator {
            // Not a place: no search (its u and v would not be finite).
            Evaluator::Crg(_) if !(x.is_finite() && y.is_finite()) => Answer::nowhere(),
            Evaluator::Crg(cp) => match cp.xy_to_uv_general(x, y) {
                Ok((u, v)) => Answer::of_crg(u, v, cp.z_of_found(u, v)),
                Err(_) => Answer::nowhere(),
            },
            Evaluator::Map(probe, _) => match probe.ground(x, y).filter(|g| g.z.is_finite()) {
                Some(g) => Answer {
                    answered: true,
                    z: g.z,
                    friction: g.friction,
                    road: i32::try_from(g.road).unwrap_or(i32::MAX),
                    lane: g.lane,
                    ..Answer::located(g.s, g.t)
                },
                None => Answer::nowhere(),
            },
        };
    }

    /// Whether the wheel is on the road (the base answer known): where the road answered
    /// the height, on a CRG file within its grid. (Worked out when asked: the hot path
    /// only stores what it found.)
    fn on_road(&self) -> bool {
        let [u0, u1, v0, v1] = self.ranges;
        let Answer { answered, a: u, b: v, .. } = self.answer;
        match self.evaluator {
            Evaluator::Crg(_) => answered && u >= u0 && u <= u1 && v >= v0 && v <= v1,
            Evaluator::Map(..) => answered,
        }
    }

    /// The discrete answers (the base answer known).
    fn discrete(&self) -> Discrete {
        (self.on_road(), self.answer.road, self.answer.lane)
    }

    /// A Real quantity (the base answer known); the height is read inline where it is
    /// the hot path.
    #[inline(never)]
    fn other(&mut self, quantity: Quantity, friction_default: f64) -> f64 {
        let a = &self.answer;
        match quantity {
            // The position the answer is of, which is the wheel's.
            Quantity::X | Quantity::Y => f64::from_bits(self.of[quantity as usize]),
            Quantity::Z => a.z,
            Quantity::EventIndicator if self.discrete() == self.latched => 1.0,
            Quantity::EventIndicator => -1.0,
            Quantity::Friction if self.on_road() && a.friction.is_finite() => a.friction,
            Quantity::Friction => friction_default,
            Quantity::U | Quantity::V | Quantity::S | Quantity::T => {
                let value = if matches!(quantity, Quantity::U | Quantity::S) { a.a } else { a.b };
                if a.located {
                    value
                } else {
                    0.0
                }
            }
            Quantity::Nx | Quantity::Ny | Quantity::Nz => self.normal()[quantity as usize - Quantity::Nx as usize],
            Quantity::Heading => self.pk().0,
            Quantity::Curvature => self.pk().1,
            _ => 0.0,
        }
    }

    /// The upward unit normal (the base answer known); up where none is known.
    fn normal(&mut self) -> [f64; 3] {
        if let Some(n) = self.answer.normal {
            return n;
        }
        let [x, y] = self.of.map(f64::from_bits);
        let a = self.answer;
        let n = if !a.answered {
            UP
        } else {
            let n = match &mut self.evaluator {
                Evaluator::Crg(cp) => cp.uv_to_normal(a.a, a.b).ok().map(|(_, n)| n),
                Evaluator::Map(_, probe) => probe.normal(x, y),
            };
            n.filter(|n| n.iter().all(|c| c.is_finite())).unwrap_or(UP)
        };
        self.answer.normal = Some(n);
        n
    }

    /// A CRG file's heading and curvature (the base answer known); 0 where none.
    fn pk(&mut self) -> (f64, f64) {
        if let Some(pk) = self.answer.pk {
            return pk;
        }
        let a = self.answer;
        let pk = match &self.evaluator {
            Evaluator::Crg(cp) if a.located => cp.uv_to_pk(a.a, a.b).ok(),
            _ => None,
        };
        let pk = pk.filter(|(p, k)| p.is_finite() && k.is_finite()).unwrap_or((0.0, 0.0));
        self.answer.pk = Some(pk);
        pk
    }
}

/// Reads a behaviour profile's name as the `compat` parameter takes it.
pub fn compat_named(name: &str) -> Result<Compat> {
    name.parse::<Compat>().map_err(|e| Error::out_of_range(format!("compat: {e}")))
}
