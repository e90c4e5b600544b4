//! The model description (`modelDescription.xml`) of an FMU, FMI 2.0 or 3.0: both
//! interfaces (model exchange and co-simulation), the variables of
//! [`variables`](crate::variables), outputs depending directly on their wheel's inputs
//! (and, at initialization, on the parameters that change them).

use crate::variables::{Causality, Kind, Parameter, Start, Type, Variability, Variable, UNITS};
use std::fmt::Write;

/// The FMI version of an FMU.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fmi {
    /// FMI 2.0.
    V2,
    /// FMI 3.0.
    V3,
}

impl Fmi {
    /// `2` or `3`.
    pub fn major(self) -> u32 {
        match self {
            Fmi::V2 => 2,
            Fmi::V3 => 3,
        }
    }
}

/// What the model description says of the FMU besides its variables.
#[derive(Debug, Clone)]
pub struct Meta {
    /// The model's name (the road file's name).
    pub model_name: String,
    /// The model identifier: the binaries' file name, a C identifier.
    pub identifier: String,
    /// The `guid` / `instantiationToken`.
    pub token: String,
    /// What the FMU answers.
    pub description: String,
    /// The program that wrote it.
    pub generation_tool: String,
    /// A map's roads' OpenDRIVE ids in the file's order: the items of the enumeration
    /// `wheel[i].road` is (none for a CRG file).
    pub roads: Vec<String>,
}

/// The enumeration type of `wheel[i].road`.
const ROAD_TYPE: &str = "Road";

/// The item of `wheel[i].road` off every road (value -1), named so unless a road has
/// that id.
fn off_road_item(roads: &[String]) -> &'static str {
    ["off road", "(off road)", "-"].into_iter().find(|name| !roads.iter().any(|id| id == name)).unwrap_or("")
}

/// The type definitions: the enumeration of a map's roads, by their ids.
fn type_definitions(x: &mut String, fmi: Fmi, roads: &[String]) {
    let items = std::iter::once((-1, off_road_item(roads)))
        .chain(roads.iter().enumerate().map(|(k, id)| (k as i64, id.as_str())))
        .map(|(value, name)| format!("      <Item name=\"{}\" value=\"{value}\"/>", escape(name)))
        .collect::<Vec<_>>()
        .join("\n");
    let _ = match fmi {
        Fmi::V2 => writeln!(
            x,
            "  <TypeDefinitions>\n    <SimpleType name=\"{ROAD_TYPE}\">\n    <Enumeration>\n{items}\n    </Enumeration>\n    </SimpleType>\n  </TypeDefinitions>"
        ),
        Fmi::V3 => writeln!(
            x,
            "  <TypeDefinitions>\n    <EnumerationType name=\"{ROAD_TYPE}\">\n{items}\n    </EnumerationType>\n  </TypeDefinitions>"
        ),
    };
}

/// Turns a file name into a model identifier: letters, digits and `_`, not starting
/// with a digit (`road` for a name left empty).
pub fn identifier_of(name: &str) -> String {
    let mut id: String = name.chars().map(|c| if c.is_ascii_alphanumeric() { c } else { '_' }).collect();
    if id.is_empty() || id.starts_with(|c: char| c.is_ascii_digit()) {
        id.insert_str(0, "road_");
    }
    id
}

fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "&#{};", c as u32);
            }
            c => out.push(c),
        }
    }
    out
}

fn number(value: f64) -> String {
    if value.is_finite() {
        format!("{value}")
    } else {
        "0".into()
    }
}

fn causality(c: Causality) -> &'static str {
    match c {
        Causality::Input => "input",
        Causality::Output => "output",
        Causality::Parameter => "parameter",
        Causality::Independent => "independent",
        Causality::Local => "local",
    }
}

fn variability(v: Variability) -> &'static str {
    match v {
        Variability::Continuous => "continuous",
        Variability::Discrete => "discrete",
        Variability::Fixed => "fixed",
        Variability::Tunable => "tunable",
    }
}

/// The parameters whose values change an output at initialization: the friction
/// default changes the friction; a CRG file's profile and options change everything.
fn initial_parameters(kind: Kind, output: &Variable) -> Vec<u32> {
    Parameter::all(kind)
        .into_iter()
        .filter(|p| match p {
            Parameter::FrictionDefault => output.name.ends_with(".friction"),
            _ => true,
        })
        .map(Parameter::vr)
        .collect()
}

/// The model description of an FMU of `kind` with these variables.
pub fn model_description(fmi: Fmi, kind: Kind, meta: &Meta, variables: &[Variable]) -> String {
    let mut x = String::new();
    let id = escape(&meta.identifier);
    let indicators: Vec<&Variable> = variables.iter().filter(|v| v.causality == Causality::Local).collect();
    let _ = writeln!(x, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>");
    let (version, token_name) = match fmi {
        Fmi::V2 => ("2.0", "guid"),
        Fmi::V3 => ("3.0", "instantiationToken"),
    };
    let _ = writeln!(
        x,
        "<fmiModelDescription\n  fmiVersion=\"{version}\"\n  modelName=\"{}\"\n  {token_name}=\"{}\"\n  description=\"{}\"\n  generationTool=\"{}\"\n  variableNamingConvention=\"structured\"{}>",
        escape(&meta.model_name),
        escape(&meta.token),
        escape(&meta.description),
        escape(&meta.generation_tool),
        match fmi {
            Fmi::V2 => format!("\n  numberOfEventIndicators=\"{}\"", indicators.len()),
            Fmi::V3 => String::new(),
        },
    );
    capabilities(&mut x, fmi, &id);
    let _ = writeln!(x, "  <UnitDefinitions>");
    for (name, m, rad) in UNITS {
        let base = match (m, rad) {
            (0, r) => format!("rad=\"{r}\""),
            (m, _) => format!("m=\"{m}\""),
        };
        let _ = writeln!(x, "    <Unit name=\"{}\"><BaseUnit {base}/></Unit>", escape(name));
    }
    let _ = writeln!(x, "  </UnitDefinitions>");
    if variables.iter().any(|v| v.ty == Type::Enumeration) {
        type_definitions(&mut x, fmi, &meta.roads);
    }
    let _ = writeln!(x, "  <LogCategories>");
    let _ = writeln!(
        x,
        "    <Category name=\"logStatusError\" description=\"calls refused and roads that cannot be loaded\"/>"
    );
    let _ = writeln!(x, "    <Category name=\"logStatusWarning\" description=\"warnings of the road's check\"/>");
    let _ = writeln!(x, "  </LogCategories>");
    let _ = writeln!(x, "  <DefaultExperiment startTime=\"0\" stepSize=\"0.001\"/>");
    let _ = writeln!(x, "  <ModelVariables>");
    for v in variables {
        match fmi {
            Fmi::V2 => variable_2(&mut x, v),
            Fmi::V3 => variable_3(&mut x, v),
        }
    }
    let _ = writeln!(x, "  </ModelVariables>");
    model_structure(&mut x, fmi, kind, variables, &indicators);
    let _ = writeln!(x, "  </ModelStructure>\n</fmiModelDescription>");
    x
}

/// The `<ModelExchange>` and `<CoSimulation>` elements: what the binary can do.
fn capabilities(x: &mut String, fmi: Fmi, id: &str) {
    match fmi {
        Fmi::V2 => {
            let common = "needsExecutionTool=\"false\" canBeInstantiatedOnlyOncePerProcess=\"false\" canNotUseMemoryManagementFunctions=\"true\" canGetAndSetFMUstate=\"false\" canSerializeFMUstate=\"false\" providesDirectionalDerivative=\"false\"";
            let _ = writeln!(
                x,
                "  <ModelExchange modelIdentifier=\"{id}\" {common} completedIntegratorStepNotNeeded=\"true\"/>"
            );
            let _ = writeln!(
                x,
                "  <CoSimulation modelIdentifier=\"{id}\" {common} canHandleVariableCommunicationStepSize=\"true\" canInterpolateInputs=\"false\" maxOutputDerivativeOrder=\"0\" canRunAsynchronuously=\"false\"/>"
            );
        }
        Fmi::V3 => {
            let common = "needsExecutionTool=\"false\" canBeInstantiatedOnlyOncePerProcess=\"false\" canGetAndSetFMUState=\"false\" canSerializeFMUState=\"false\" providesDirectionalDerivatives=\"false\" providesAdjointDerivatives=\"false\"";
            let _ = writeln!(
                x,
                "  <ModelExchange modelIdentifier=\"{id}\" {common} needsCompletedIntegratorStep=\"false\"/>"
            );
            let _ = writeln!(
                x,
                "  <CoSimulation modelIdentifier=\"{id}\" {common} canHandleVariableCommunicationStepSize=\"true\" maxOutputDerivativeOrder=\"0\" providesIntermediateUpdate=\"false\" mightReturnEarlyFromDoStep=\"false\" canReturnEarlyAfterIntermediateUpdate=\"false\" hasEventMode=\"false\"/>"
            );
        }
    }
}

/// The `<ModelStructure>`: the outputs, the initial unknowns with what they depend on,
/// and (FMI 3) the event indicators.
fn model_structure(x: &mut String, fmi: Fmi, kind: Kind, variables: &[Variable], indicators: &[&Variable]) {
    let _ = writeln!(x, "  <ModelStructure>");
    // FMI 2 names variables by their index in the list (from 1), FMI 3 by value reference.
    let index_of = |vr: u32| -> u32 {
        match fmi {
            Fmi::V2 => variables.iter().position(|v| v.vr == vr).map_or(0, |i| i as u32 + 1),
            Fmi::V3 => vr,
        }
    };
    let outputs: Vec<&Variable> = variables.iter().filter(|v| v.causality == Causality::Output).collect();
    let unknown = |x: &mut String, element: &str, v: &Variable, depends: &[u32]| {
        let list: Vec<String> = depends.iter().map(|&d| index_of(d).to_string()).collect();
        let kinds = vec!["dependent"; list.len()].join(" ");
        let at = match fmi {
            Fmi::V2 => format!("index=\"{}\"", index_of(v.vr)),
            Fmi::V3 => format!("valueReference=\"{}\"", v.vr),
        };
        let _ = writeln!(x, "    {element} {at} dependencies=\"{}\" dependenciesKind=\"{kinds}\"/>", list.join(" "));
    };
    let (output, initial) = match fmi {
        Fmi::V2 => ("  <Unknown", "  <Unknown"),
        Fmi::V3 => ("<Output", "<InitialUnknown"),
    };
    if fmi == Fmi::V2 {
        let _ = writeln!(x, "    <Outputs>");
    }
    for v in &outputs {
        unknown(x, output, v, &v.depends_on);
    }
    if fmi == Fmi::V2 {
        let _ = writeln!(x, "    </Outputs>\n    <InitialUnknowns>");
    }
    for v in &outputs {
        let mut depends = v.depends_on.clone();
        depends.extend(initial_parameters(kind, v));
        // FMI 2 lists the dependencies by index, in increasing order.
        depends.sort_by_key(|&d| index_of(d));
        unknown(x, initial, v, &depends);
    }
    match fmi {
        Fmi::V2 => {
            let _ = writeln!(x, "    </InitialUnknowns>");
        }
        // FMI 3 names its event indicators here (FMI 2 counts them, in the wheels' order).
        Fmi::V3 => indicators.iter().for_each(|v| unknown(x, "<EventIndicator", v, &v.depends_on)),
    }
}

fn attributes(v: &Variable) -> String {
    let mut a = format!(
        "name=\"{}\" valueReference=\"{}\" causality=\"{}\" variability=\"{}\"",
        escape(&v.name),
        v.vr,
        causality(v.causality),
        variability(v.variability)
    );
    if v.causality == Causality::Parameter {
        a.push_str(" initial=\"exact\"");
    }
    let _ = write!(a, " description=\"{}\"", escape(&v.description));
    a
}

fn variable_2(x: &mut String, v: &Variable) {
    let element = match v.ty {
        Type::Real => "Real",
        Type::Integer => "Integer",
        Type::Enumeration => "Enumeration",
        Type::Boolean => "Boolean",
        Type::String => "String",
    };
    let mut inner = String::new();
    if v.ty == Type::Enumeration {
        inner.push_str(&format!(" declaredType=\"{ROAD_TYPE}\""));
    }
    match &v.start {
        Some(Start::Real(r)) => inner.push_str(&format!(" start=\"{}\"", number(*r))),
        Some(Start::Integer(i)) => inner.push_str(&format!(" start=\"{i}\"")),
        Some(Start::Boolean(b)) => inner.push_str(&format!(" start=\"{b}\"")),
        Some(Start::String(s)) => inner.push_str(&format!(" start=\"{}\"", escape(s))),
        None => {}
    }
    if let Some(unit) = v.unit {
        inner.push_str(&format!(" unit=\"{}\"", escape(unit)));
    }
    let _ = writeln!(x, "    <ScalarVariable {}>\n      <{element}{inner}/>\n    </ScalarVariable>", attributes(v));
}

fn variable_3(x: &mut String, v: &Variable) {
    let element = match v.ty {
        Type::Real => "Float64",
        Type::Integer => "Int32",
        Type::Enumeration => "Enumeration",
        Type::Boolean => "Boolean",
        Type::String => "String",
    };
    let mut a = attributes(v);
    if v.ty == Type::Enumeration {
        a.push_str(&format!(" declaredType=\"{ROAD_TYPE}\""));
    }
    let mut body = None;
    match &v.start {
        Some(Start::Real(r)) => a.push_str(&format!(" start=\"{}\"", number(*r))),
        Some(Start::Integer(i)) => a.push_str(&format!(" start=\"{i}\"")),
        Some(Start::Boolean(b)) => a.push_str(&format!(" start=\"{b}\"")),
        Some(Start::String(s)) => body = Some(format!("<Start value=\"{}\"/>", escape(s))),
        None => {}
    }
    if let Some(unit) = v.unit {
        a.push_str(&format!(" unit=\"{}\"", escape(unit)));
    }
    match body {
        Some(body) => {
            let _ = writeln!(x, "    <{element} {a}>{body}</{element}>");
        }
        None => {
            let _ = writeln!(x, "    <{element} {a}/>");
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identifiers_are_c_identifiers() {
        assert_eq!(identifier_of("demo_road"), "demo_road");
        assert_eq!(identifier_of("Town 03-b"), "Town_03_b");
        assert_eq!(identifier_of("3lanes"), "road_3lanes");
        assert_eq!(identifier_of(""), "road_");
        assert_eq!(identifier_of("Straße"), "Stra_e");
    }

    #[test]
    fn roads_are_items_named_by_their_ids() {
        let roads = vec!["1".to_string(), "off road".to_string(), "a<b".to_string()];
        for fmi in [Fmi::V2, Fmi::V3] {
            let mut x = String::new();
            type_definitions(&mut x, fmi, &roads);
            for item in ["name=\"(off road)\" value=\"-1\"", "name=\"1\" value=\"0\"", "name=\"a&lt;b\" value=\"2\""] {
                assert!(x.contains(item), "{item} in {x}");
            }
        }
        assert_eq!(off_road_item(&[]), "off road");
    }

    #[test]
    fn text_is_escaped() {
        assert_eq!(escape("a<b & \"c\"\n"), "a&lt;b &amp; &quot;c&quot;&#10;");
    }
}
