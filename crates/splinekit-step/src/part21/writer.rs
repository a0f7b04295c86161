//! Writing ISO 10303-21 files: header, numbered instances, parameters encoded exactly
//! (reals in shortest round-trip form, so a reader gets the same doubles back), lines
//! wrapped between tokens near 80 columns.

use crate::part21::lexer::encode_string;
use crate::part21::parser::{Param, Record};

/// The schema written by default: AP214 (`AUTOMOTIVE_DESIGN`), which AP242 readers read too.
pub const AP214_SCHEMA: &str = "AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }";

/// What goes into the header section.
#[derive(Debug, Clone, PartialEq)]
pub struct HeaderInfo {
    /// `FILE_DESCRIPTION` text.
    pub description: String,
    /// `FILE_NAME` name.
    pub name: String,
    /// `FILE_NAME` time stamp (ISO 8601).
    pub time_stamp: String,
    /// `FILE_NAME` preprocessor and originating system.
    pub system: String,
    /// `FILE_SCHEMA`.
    pub schema: String,
}

impl Default for HeaderInfo {
    fn default() -> Self {
        HeaderInfo {
            description: "splinekit exact geometry".into(),
            name: String::new(),
            time_stamp: "1970-01-01T00:00:00".into(),
            system: format!("splinekit {}", env!("CARGO_PKG_VERSION")),
            schema: AP214_SCHEMA.into(),
        }
    }
}

impl HeaderInfo {
    /// The default header named `name`, stamped with the current UTC time.
    pub fn now(name: &str) -> HeaderInfo {
        let secs = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs()) as i64;
        HeaderInfo { name: name.to_string(), time_stamp: iso8601_utc(secs), ..HeaderInfo::default() }
    }
}

/// Seconds since 1970-01-01T00:00:00 UTC as ISO 8601 (`YYYY-MM-DDThh:mm:ss`), the civil
/// date by Howard Hinnant's `civil_from_days` (exact over the proleptic Gregorian calendar).
pub fn iso8601_utc(secs: i64) -> String {
    let (days, rem) = (secs.div_euclid(86_400), secs.rem_euclid(86_400));
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!("{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}", rem / 3600, rem % 3600 / 60, rem % 60)
}

/// Writes instances `#1, #2, …` in the order they are added.
#[derive(Debug, Clone)]
pub struct Part21Writer {
    out: String,
    column: usize,
    next_id: u64,
}

/// Formats a real so that it reads back as the same double and has the `.` Part 21 needs:
/// `1.`, `-0.25`, `1.5E-07`.
pub fn format_real(x: f64) -> String {
    let s = format!("{x:?}");
    let (mantissa, exponent) = match s.split_once('e') {
        Some((m, e)) => (m.to_string(), Some(e.to_string())),
        None => (s, None),
    };
    let mantissa = if mantissa.contains('.') {
        mantissa.strip_suffix(".0").map(|m| format!("{m}.")).unwrap_or(mantissa)
    } else {
        format!("{mantissa}.")
    };
    match exponent {
        Some(e) => format!("{mantissa}E{e}"),
        None => mantissa,
    }
}

impl Part21Writer {
    /// Starts a file with the given header; instances follow in the data section.
    pub fn new(header: &HeaderInfo) -> Self {
        let mut w = Part21Writer { out: String::new(), column: 0, next_id: 1 };
        w.out.push_str("ISO-10303-21;\nHEADER;\n");
        let s = |t: &str| Param::String(t.to_string());
        let records = [
            Record {
                name: "FILE_DESCRIPTION".into(),
                params: vec![Param::List(vec![s(&header.description)]), s("2;1")],
            },
            Record {
                name: "FILE_NAME".into(),
                params: vec![
                    s(&header.name),
                    s(&header.time_stamp),
                    Param::List(vec![s("")]),
                    Param::List(vec![s("")]),
                    s(&header.system),
                    s(&header.system),
                    s(""),
                ],
            },
            Record { name: "FILE_SCHEMA".into(), params: vec![Param::List(vec![s(&header.schema)])] },
        ];
        for r in &records {
            w.record(r);
            w.token(";");
            w.newline();
        }
        w.out.push_str("ENDSEC;\nDATA;\n");
        w
    }

    /// Adds a simple instance and returns its `#id`.
    pub fn add(&mut self, name: &str, params: Vec<Param>) -> u64 {
        let id = self.begin();
        self.record(&Record { name: name.to_string(), params });
        self.end();
        id
    }

    /// Adds a complex instance `( A(..) B(..) … )` (records sorted by name, as the
    /// standard asks) and returns its `#id`.
    pub fn add_complex(&mut self, mut records: Vec<Record>) -> u64 {
        records.sort_by(|a, b| a.name.cmp(&b.name));
        let id = self.begin();
        self.token("(");
        for r in &records {
            self.token(" ");
            self.record(r);
        }
        self.token(" )");
        self.end();
        id
    }

    /// The file text.
    pub fn finish(mut self) -> String {
        self.out.push_str("ENDSEC;\nEND-ISO-10303-21;\n");
        self.out
    }

    fn begin(&mut self) -> u64 {
        let id = self.next_id;
        self.next_id += 1;
        self.token(&format!("#{id}="));
        id
    }

    fn end(&mut self) {
        self.token(";");
        self.newline();
    }

    fn newline(&mut self) {
        self.out.push('\n');
        self.column = 0;
    }

    /// Appends a token, breaking the line first when it would pass 80 columns.
    fn token(&mut self, t: &str) {
        if self.column > 0 && self.column + t.len() > 78 {
            self.out.push_str("\n  ");
            self.column = 2;
        }
        self.out.push_str(t);
        self.column += t.len();
    }

    fn record(&mut self, r: &Record) {
        self.token(&format!("{}(", r.name));
        self.params(&r.params);
        self.token(")");
    }

    fn params(&mut self, params: &[Param]) {
        for (i, p) in params.iter().enumerate() {
            self.param(p);
            if i + 1 < params.len() {
                self.token(",");
            }
        }
    }

    fn param(&mut self, p: &Param) {
        match p {
            Param::Unset => self.token("$"),
            Param::Derived => self.token("*"),
            Param::Integer(i) => self.token(&i.to_string()),
            Param::Real(x) => self.token(&format_real(*x)),
            Param::String(s) => self.token(&encode_string(s)),
            Param::Enumeration(e) => self.token(&format!(".{e}.")),
            Param::Binary(b) => self.token(&format!("\"{b}\"")),
            Param::Reference(id) => self.token(&format!("#{id}")),
            Param::List(items) => {
                self.token("(");
                self.params(items);
                self.token(")");
            }
            Param::Typed(name, inner) => {
                self.token(&format!("{name}("));
                self.param(inner);
                self.token(")");
            }
        }
    }
}

#[cfg(test)]
mod tests {

    #[test]
    fn iso8601_dates_match_known_calendar_days() {
        assert_eq!(super::iso8601_utc(0), "1970-01-01T00:00:00");
        // 2000-02-29 12:34:56 (a leap day of a century divisible by 400): `date -u -d ... +%s`.
        assert_eq!(super::iso8601_utc(951_827_696), "2000-02-29T12:34:56");
        assert_eq!(super::iso8601_utc(1_796_601_600), "2026-12-07T00:00:00");
        assert_eq!(super::iso8601_utc(-1), "1969-12-31T23:59:59");
    }
    use super::*;
    use crate::part21::file::StepFile;

    #[test]
    fn reals_keep_a_dot_and_round_trip() {
        assert_eq!(format_real(1.0), "1.");
        assert_eq!(format_real(-0.25), "-0.25");
        assert_eq!(format_real(1.5e-7), "1.5E-7");
        assert_eq!(format_real(1e300), "1.E300");
        for x in [0.1, 1.0 / 3.0, std::f64::consts::PI, -2.5e-310, 6.02e23, -0.0] {
            let s = format_real(x);
            assert_eq!(s.parse::<f64>().unwrap().to_bits(), x.to_bits(), "{s}");
        }
    }

    #[test]
    fn written_files_read_back() {
        let mut w = Part21Writer::new(&HeaderInfo::default());
        let long: Vec<Param> = (0..40).map(|i| Param::Real(i as f64 / 7.0)).collect();
        let p = w.add("CARTESIAN_POINT", vec![Param::String("it's".into()), Param::List(long.clone())]);
        let c = w.add_complex(vec![
            Record { name: "CURVE".into(), params: vec![] },
            Record { name: "BOUNDED_CURVE".into(), params: vec![Param::Reference(p)] },
        ]);
        let f = StepFile::from_bytes(w.finish().into_bytes()).unwrap();
        assert_eq!(f.get(p).unwrap().records[0].params[1], Param::List(long));
        assert_eq!(f.type_of(c), Some("(BOUNDED_CURVE CURVE)"));
    }
}
