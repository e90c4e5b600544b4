//! Surfaces written as formulas of u and v, for `generate --surface`: numbers, `u`,
//! `v`, `pi`, `+ - * / ^`, parentheses and sin, cos, tan, exp, ln, sqrt, abs.

/// A parsed formula.
#[derive(Debug, Clone)]
pub enum Expr {
    Number(f64),
    U,
    V,
    Neg(Box<Expr>),
    Binary(char, Box<Expr>, Box<Expr>),
    Call(fn(f64) -> f64, Box<Expr>),
}

impl Expr {
    /// The formula's value at (u, v).
    pub fn at(&self, u: f64, v: f64) -> f64 {
        match self {
            Expr::Number(x) => *x,
            Expr::U => u,
            Expr::V => v,
            Expr::Neg(e) => -e.at(u, v),
            Expr::Binary(op, a, b) => {
                let (a, b) = (a.at(u, v), b.at(u, v));
                match op {
                    '+' => a + b,
                    '-' => a - b,
                    '*' => a * b,
                    '/' => a / b,
                    _ => a.powf(b),
                }
            }
            Expr::Call(f, e) => f(e.at(u, v)),
        }
    }
}

/// The longest formula taken, in bytes: its tree is at most half as deep, which
/// evaluating and dropping it walk recursively.
const MAX_LENGTH: usize = 10_000;
/// The deepest the parser descends: each parenthesis or call takes two levels, each sign
/// or power one.
const MAX_NESTING: usize = 200;

/// `text` as a message quotes it: its first 60 characters and an ellipsis when longer.
pub fn abridged(text: &str) -> String {
    match text.char_indices().nth(60) {
        Some((end, _)) => format!("{}...", &text[..end]),
        None => text.to_string(),
    }
}

/// Parses `text`; the error says what was expected where.
pub fn parse(text: &str) -> Result<Expr, String> {
    if text.len() > MAX_LENGTH {
        return Err(format!("a formula of {} characters; at most {MAX_LENGTH} are taken", text.len()));
    }
    let mut p = Parser { s: text.as_bytes(), at: 0, nesting: 0 };
    let e = p.sum()?;
    p.blanks();
    if p.at < p.s.len() {
        return Err(p.expected("an operator or the end"));
    }
    Ok(e)
}

struct Parser<'a> {
    s: &'a [u8],
    at: usize,
    /// How deep the parser has descended into nested parts.
    nesting: usize,
}

impl Parser<'_> {
    fn blanks(&mut self) {
        while self.s.get(self.at).is_some_and(u8::is_ascii_whitespace) {
            self.at += 1;
        }
    }

    fn peek(&mut self) -> Option<u8> {
        self.blanks();
        self.s.get(self.at).copied()
    }

    fn expected(&self, what: &str) -> String {
        format!("expected {what} at character {}", self.at + 1)
    }

    fn sum(&mut self) -> Result<Expr, String> {
        self.chain(b"+-", Self::product)
    }

    fn product(&mut self) -> Result<Expr, String> {
        self.chain(b"*/", Self::unary)
    }

    /// Operands from `operand` joined left to right by the operators `ops`.
    fn chain(&mut self, ops: &[u8], operand: fn(&mut Self) -> Result<Expr, String>) -> Result<Expr, String> {
        let mut e = operand(self)?;
        while let Some(op) = self.peek().filter(|c| ops.contains(c)) {
            self.at += 1;
            e = Expr::Binary(op as char, Box::new(e), Box::new(operand(self)?));
        }
        Ok(e)
    }

    /// `part` one level deeper, refused beyond [`MAX_NESTING`].
    fn nested(&mut self, part: fn(&mut Self) -> Result<Expr, String>) -> Result<Expr, String> {
        if self.nesting >= MAX_NESTING {
            return Err(format!("more than {MAX_NESTING} nested parts at character {}", self.at + 1));
        }
        self.nesting += 1;
        let e = part(self);
        self.nesting -= 1;
        e
    }

    fn unary(&mut self) -> Result<Expr, String> {
        self.nested(Self::unary_here)
    }

    fn unary_here(&mut self) -> Result<Expr, String> {
        if self.peek() == Some(b'-') {
            self.at += 1;
            return Ok(Expr::Neg(Box::new(self.unary()?)));
        }
        let base = self.atom()?;
        if self.peek() == Some(b'^') {
            self.at += 1;
            return Ok(Expr::Binary('^', Box::new(base), Box::new(self.unary()?)));
        }
        Ok(base)
    }

    fn atom(&mut self) -> Result<Expr, String> {
        match self.peek() {
            Some(b'(') => {
                self.at += 1;
                let e = self.nested(Self::sum)?;
                if self.peek() != Some(b')') {
                    return Err(self.expected("')'"));
                }
                self.at += 1;
                Ok(e)
            }
            Some(c) if c.is_ascii_digit() || c == b'.' => {
                let start = self.at;
                while self.s.get(self.at).is_some_and(|c| c.is_ascii_digit() || *c == b'.') {
                    self.at += 1;
                }
                if self.s.get(self.at).is_some_and(|c| *c == b'e' || *c == b'E') {
                    self.at += 1;
                    if self.s.get(self.at).is_some_and(|c| *c == b'+' || *c == b'-') {
                        self.at += 1;
                    }
                    while self.s.get(self.at).is_some_and(u8::is_ascii_digit) {
                        self.at += 1;
                    }
                }
                let text = std::str::from_utf8(&self.s[start..self.at]).unwrap_or("");
                text.parse().map(Expr::Number).map_err(|_| format!("'{text}' is not a number"))
            }
            Some(c) if c.is_ascii_alphabetic() => {
                let start = self.at;
                while self.s.get(self.at).is_some_and(u8::is_ascii_alphanumeric) {
                    self.at += 1;
                }
                let name = std::str::from_utf8(&self.s[start..self.at]).unwrap_or("");
                let f: fn(f64) -> f64 = match name {
                    "u" => return Ok(Expr::U),
                    "v" => return Ok(Expr::V),
                    "pi" => return Ok(Expr::Number(std::f64::consts::PI)),
                    "sin" => f64::sin,
                    "cos" => f64::cos,
                    "tan" => f64::tan,
                    "exp" => f64::exp,
                    "ln" => f64::ln,
                    "sqrt" => f64::sqrt,
                    "abs" => f64::abs,
                    _ => return Err(format!("unknown name '{name}' (u, v, pi, sin, cos, tan, exp, ln, sqrt, abs)")),
                };
                if self.peek() != Some(b'(') {
                    return Err(self.expected(&format!("'(' after {name}")));
                }
                self.at += 1;
                let arg = self.nested(Self::sum)?;
                if self.peek() != Some(b')') {
                    return Err(self.expected("')'"));
                }
                self.at += 1;
                Ok(Expr::Call(f, Box::new(arg)))
            }
            _ => Err(self.expected("a number, u, v, a function or '('")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::parse;

    #[test]
    fn formulas_evaluate_with_the_usual_precedence() {
        let e = parse("0.01*sin(2*pi*u/5) + -v^2/4 - 1e-3").unwrap();
        let (u, v) = (1.3, 0.7);
        let want = 0.01 * (2.0 * std::f64::consts::PI * u / 5.0).sin() - v * v / 4.0 - 1e-3;
        assert!((e.at(u, v) - want).abs() < 1e-15);
        assert_eq!(parse("2^3^2").unwrap().at(0.0, 0.0), 512.0);
        assert!(parse("sin u").unwrap_err().contains("'(' after sin"));
        assert!(parse("w + 1").unwrap_err().contains("unknown name 'w'"));
        assert!(parse("(u").unwrap_err().contains("')'"));
    }

    #[test]
    fn deep_or_long_formulas_are_refused_not_overflowing() {
        let deep = format!("{}u{}", "(".repeat(3000), ")".repeat(3000));
        assert!(parse(&deep).unwrap_err().contains("nested"));
        assert!(parse(&format!("{}u", "-".repeat(5000))).unwrap_err().contains("nested"));
        assert!(parse(&"u+".repeat(6000)).unwrap_err().contains("at most"));
        let long = format!("u{}", "+u".repeat(4000));
        assert_eq!(parse(&long).unwrap().at(1.0, 0.0), 4001.0);
        assert!(parse(&format!("{}u{}", "(".repeat(90), ")".repeat(90))).is_ok());
    }
}
