//! The grammar of ISO 10303-21 records on top of the [`Lexer`]: parameters, simple and
//! complex entity instances, header records.
//!
//! ```text
//! instance  = "#id" "=" ( record | "(" record { record } ")" ) ";"
//! record    = KEYWORD "(" [ parameter { "," parameter } ] ")"
//! parameter = KEYWORD "(" parameter ")"          (typed)
//!           | "(" [ parameter { "," parameter } ] ")"   (list)
//!           | INTEGER | REAL | STRING | "#id" | .ENUM. | BINARY | "$" | "*"
//! ```

use crate::error::{Result, StepError};
use crate::part21::lexer::{ByteSource, Lexer, Token};

/// Deepest nesting of lists and typed parameters accepted (no real schema comes close;
/// the bound keeps a hostile file from exhausting the stack).
pub const MAX_NESTING: usize = 64;

/// A parameter value.
#[derive(Debug, Clone, PartialEq)]
pub enum Param {
    /// `$`: no value.
    Unset,
    /// `*`: derived by the schema.
    Derived,
    /// An integer.
    Integer(i64),
    /// A real.
    Real(f64),
    /// A string.
    String(String),
    /// An enumeration value (without dots), e.g. `T`, `UNSPECIFIED`.
    Enumeration(String),
    /// A binary (hex digits).
    Binary(String),
    /// A reference to entity instance `#id`.
    Reference(u64),
    /// A list, set or bag.
    List(Vec<Param>),
    /// A typed parameter `NAME(value)`, e.g. `LENGTH_MEASURE(1.E-07)`.
    Typed(String, Box<Param>),
}

impl Param {
    /// Calls `f` with every entity reference inside the parameter.
    pub fn for_each_reference(&self, f: &mut impl FnMut(u64)) {
        match self {
            Param::Reference(id) => f(*id),
            Param::List(items) => items.iter().for_each(|p| p.for_each_reference(f)),
            Param::Typed(_, inner) => inner.for_each_reference(f),
            _ => {}
        }
    }
}

/// One record: an entity type name and its parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    /// The type name, e.g. `CARTESIAN_POINT`.
    pub name: String,
    /// Its parameters in order.
    pub params: Vec<Param>,
}

/// An entity instance: one record (simple) or several (complex, `(A(..) B(..))`).
#[derive(Debug, Clone, PartialEq)]
pub struct Instance {
    /// The instance name `#id`.
    pub id: u64,
    /// The line it starts on.
    pub line: u32,
    /// Its records (more than one for a complex instance).
    pub records: Vec<Record>,
}

impl Instance {
    /// Whether this is a complex instance.
    pub fn is_complex(&self) -> bool {
        self.records.len() > 1
    }
    /// The record of type `name`, if the instance has one.
    pub fn record(&self, name: &str) -> Option<&Record> {
        self.records.iter().find(|r| r.name == name)
    }
    /// The type name of a simple instance, or `(A B C)` for a complex one.
    pub fn type_name(&self) -> String {
        if let [r] = self.records.as_slice() {
            r.name.clone()
        } else {
            format!("({})", self.records.iter().map(|r| r.name.as_str()).collect::<Vec<_>>().join(" "))
        }
    }
}

/// A recursive-descent parser with one token of look-ahead.
pub struct Parser<S> {
    lexer: Lexer<S>,
    ahead: Option<Token>,
}

impl<S: ByteSource> Parser<S> {
    /// A parser reading from `lexer`.
    pub fn new(lexer: Lexer<S>) -> Self {
        Parser { lexer, ahead: None }
    }

    /// The underlying lexer (positions of the last token).
    pub fn lexer(&self) -> &Lexer<S> {
        &self.lexer
    }

    /// The next token without consuming it.
    pub fn peek(&mut self) -> Result<&Token> {
        if self.ahead.is_none() {
            self.ahead = Some(self.lexer.next_token()?);
        }
        Ok(self.ahead.as_ref().expect("just filled"))
    }

    /// Consumes and returns the next token.
    pub fn next_token(&mut self) -> Result<Token> {
        match self.ahead.take() {
            Some(t) => Ok(t),
            None => self.lexer.next_token(),
        }
    }

    /// Line of the last token read.
    pub fn token_line(&self) -> u32 {
        self.lexer.token_line
    }

    fn unexpected(&self, got: &Token, wanted: &str) -> StepError {
        StepError::at(self.token_line(), None, format!("expected {wanted}, got {}", got.describe()))
    }

    /// Consumes `want` or fails naming what came instead.
    pub fn expect(&mut self, want: &Token, what: &str) -> Result<()> {
        let t = self.next_token()?;
        if &t == want { Ok(()) } else { Err(self.unexpected(&t, what)) }
    }

    /// Consumes the keyword `word` followed by `;` (e.g. `HEADER;`).
    pub fn expect_section(&mut self, word: &str) -> Result<()> {
        match self.next_token()? {
            Token::Keyword(k) if k == word => self.expect(&Token::Semicolon, "';'"),
            t => Err(self.unexpected(&t, word)),
        }
    }

    /// A parenthesised parameter list `( p, p, … )` (the `(` not yet consumed).
    fn param_list(&mut self, depth: usize) -> Result<Vec<Param>> {
        if depth > MAX_NESTING {
            return Err(StepError::at(self.token_line(), None, format!("lists nested deeper than {MAX_NESTING}")));
        }
        self.expect(&Token::Open, "'('")?;
        let mut out = Vec::new();
        if *self.peek()? == Token::Close {
            self.next_token()?;
            return Ok(out);
        }
        loop {
            out.push(self.param(depth)?);
            match self.next_token()? {
                Token::Comma => {}
                Token::Close => return Ok(out),
                t => return Err(self.unexpected(&t, "',' or ')'")),
            }
        }
    }

    fn param(&mut self, depth: usize) -> Result<Param> {
        if *self.peek()? == Token::Open {
            return Ok(Param::List(self.param_list(depth + 1)?));
        }
        Ok(match self.next_token()? {
            Token::Unset => Param::Unset,
            Token::Derived => Param::Derived,
            Token::Integer(i) => Param::Integer(i),
            Token::Real(x) => Param::Real(x),
            Token::String(s) => Param::String(s),
            Token::Enumeration(e) => Param::Enumeration(e),
            Token::Binary(b) => Param::Binary(b),
            Token::EntityName(id) => Param::Reference(id),
            Token::Keyword(name) => {
                let mut inner = self.param_list(depth + 1)?;
                if inner.len() != 1 {
                    return Err(StepError::at(
                        self.token_line(),
                        None,
                        format!("typed parameter {name}(…) must hold one value, got {}", inner.len()),
                    ));
                }
                Param::Typed(name, Box::new(inner.pop().expect("one")))
            }
            t => return Err(self.unexpected(&t, "a parameter")),
        })
    }

    /// `KEYWORD ( params )`.
    pub fn record(&mut self) -> Result<Record> {
        match self.next_token()? {
            Token::Keyword(name) => Ok(Record { name, params: self.param_list(0)? }),
            t => Err(self.unexpected(&t, "an entity type name")),
        }
    }

    /// The rest of an instance after its `#id` token: `= record ;` or `= ( records ) ;`.
    /// Errors name the instance.
    pub fn instance_body(&mut self, id: u64, line: u32) -> Result<Instance> {
        let records = (|| {
            self.expect(&Token::Equals, "'='")?;
            let records = if *self.peek()? == Token::Open {
                self.next_token()?;
                let mut records = Vec::new();
                while *self.peek()? != Token::Close {
                    records.push(self.record()?);
                }
                self.next_token()?;
                if records.is_empty() {
                    return Err(StepError::at(self.token_line(), None, "a complex instance needs at least one record"));
                }
                records
            } else {
                vec![self.record()?]
            };
            self.expect(&Token::Semicolon, "';' after the instance")?;
            Ok(records)
        })()
        .map_err(|e: StepError| StepError::at(e.location.line, Some(id), e.message))?;
        Ok(Instance { id, line, records })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::part21::lexer::SliceSource;

    fn instance(text: &str) -> Result<Instance> {
        let mut p = Parser::new(Lexer::new(SliceSource::new(text.as_bytes()), 1, 0));
        match p.next_token()? {
            Token::EntityName(id) => {
                let line = p.token_line();
                p.instance_body(id, line)
            }
            t => panic!("{t:?}"),
        }
    }

    #[test]
    fn simple_and_complex_instances() {
        let i = instance("#7=CARTESIAN_POINT('',(0.,1.5,-2.));").unwrap();
        assert_eq!(i.id, 7);
        assert_eq!(i.records[0].params[1], Param::List(vec![Param::Real(0.0), Param::Real(1.5), Param::Real(-2.0)]));
        let c = instance("#8=( BOUNDED_CURVE() B_SPLINE_CURVE(2,(#1,#2),.UNSPECIFIED.,.F.,.F.) CURVE() );").unwrap();
        assert!(c.is_complex());
        assert_eq!(c.type_name(), "(BOUNDED_CURVE B_SPLINE_CURVE CURVE)");
        assert_eq!(c.record("B_SPLINE_CURVE").unwrap().params[0], Param::Integer(2));
        let t = instance("#9=UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),#3,'a','b');").unwrap();
        assert_eq!(t.records[0].params[0], Param::Typed("LENGTH_MEASURE".into(), Box::new(Param::Real(1e-7))));
    }

    #[test]
    fn errors_name_line_and_entity() {
        let e = instance("#5=A(1,\n2;").unwrap_err();
        assert_eq!((e.location.line, e.location.entity), (2, Some(5)));
        assert!(e.message.contains("',' or ')'"), "{e}");
        let deep = format!("#1=A({}{});", "(".repeat(100), ")".repeat(100));
        assert!(instance(&deep).unwrap_err().message.contains("nested"));
        assert!(instance("#1=A(B(1,2));").unwrap_err().message.contains("typed"));
    }
}
