//! The tokens of an ISO 10303-21 exchange structure, read from a byte stream one at a time
//! (never the whole file in memory), with line numbers for messages.
//!
//! Token syntax (ISO 10303-21 §5): entity instance names `#123`; keywords `CIRCLE`,
//! `!USER_KEYWORD`, and the framing words `ISO-10303-21`, `HEADER`, `DATA`, `ENDSEC`,
//! `END-ISO-10303-21`; integers `-12`; reals `1.`, `-2.5E-07` (a real always has a `.`);
//! strings `'it''s'` with the escapes `\\`, `\S\c`, `\P?\`, `\X\hh`, `\X2\…\X0\`,
//! `\X4\…\X0\` (and UTF-8 text as edition 3 allows); enumerations `.T.`; binaries
//! `"0FF"`; `$` (unset), `*` (derived); punctuation `( ) , ; =`; comments `/* … */`
//! wherever white space may stand.

use std::io::Read;

use crate::error::{Result, StepError};

/// Longest string, keyword or number token accepted (bytes): a guard against input that
/// would make one token eat the machine's memory.
pub const MAX_TOKEN_BYTES: usize = 1 << 24;

/// A token.
#[derive(Debug, Clone, PartialEq)]
pub enum Token {
    /// `#id`.
    EntityName(u64),
    /// A keyword (entity type name, section name).
    Keyword(String),
    /// An integer.
    Integer(i64),
    /// A real number.
    Real(f64),
    /// A decoded string.
    String(String),
    /// An enumeration value `.NAME.` (the name without dots).
    Enumeration(String),
    /// A binary `"…"` (the hex digits).
    Binary(String),
    /// `$`.
    Unset,
    /// `*`.
    Derived,
    /// `(`.
    Open,
    /// `)`.
    Close,
    /// `,`.
    Comma,
    /// `;`.
    Semicolon,
    /// `=`.
    Equals,
    /// The end of the input.
    End,
}

impl Token {
    /// How the token reads in a message.
    pub fn describe(&self) -> String {
        match self {
            Token::EntityName(id) => format!("#{id}"),
            Token::Keyword(k) => format!("keyword {k}"),
            Token::Integer(i) => format!("integer {i}"),
            Token::Real(r) => format!("real {r}"),
            Token::String(_) => "a string".into(),
            Token::Enumeration(e) => format!(".{e}."),
            Token::Binary(_) => "a binary".into(),
            Token::Unset => "'$'".into(),
            Token::Derived => "'*'".into(),
            Token::Open => "'('".into(),
            Token::Close => "')'".into(),
            Token::Comma => "','".into(),
            Token::Semicolon => "';'".into(),
            Token::Equals => "'='".into(),
            Token::End => "the end of the file".into(),
        }
    }
}

/// Bytes with one byte of look-ahead.
pub trait ByteSource {
    /// The next byte without consuming it; `None` at the end.
    fn peek(&mut self) -> Option<u8>;
    /// Consumes the byte [`ByteSource::peek`] returned.
    fn bump(&mut self);
    /// A read error met on the way (reported instead of a silent end).
    fn take_error(&mut self) -> Option<std::io::Error> {
        None
    }
}

/// Bytes of a slice in memory.
pub struct SliceSource<'a> {
    data: &'a [u8],
    pos: usize,
}

impl<'a> SliceSource<'a> {
    /// Reads `data` from its start.
    pub fn new(data: &'a [u8]) -> Self {
        SliceSource { data, pos: 0 }
    }
}

impl ByteSource for SliceSource<'_> {
    #[inline]
    fn peek(&mut self) -> Option<u8> {
        self.data.get(self.pos).copied()
    }
    #[inline]
    fn bump(&mut self) {
        self.pos += 1;
    }
}

/// Bytes of any reader, through a fixed 64 KiB buffer (the memory bound of streaming).
pub struct ReaderSource<R> {
    reader: R,
    buf: Box<[u8]>,
    pos: usize,
    len: usize,
    error: Option<std::io::Error>,
}

impl<R: Read> ReaderSource<R> {
    /// Streams `reader`.
    pub fn new(reader: R) -> Self {
        ReaderSource { reader, buf: vec![0; 1 << 16].into_boxed_slice(), pos: 0, len: 0, error: None }
    }
    #[cold]
    fn refill(&mut self) {
        if self.error.is_some() {
            return;
        }
        loop {
            match self.reader.read(&mut self.buf) {
                Ok(n) => {
                    self.pos = 0;
                    self.len = n;
                    return;
                }
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
                Err(e) => {
                    self.error = Some(e);
                    self.pos = 0;
                    self.len = 0;
                    return;
                }
            }
        }
    }
}

impl<R: Read> ByteSource for ReaderSource<R> {
    #[inline]
    fn peek(&mut self) -> Option<u8> {
        if self.pos == self.len {
            self.refill();
            if self.len == 0 {
                return None;
            }
        }
        Some(self.buf[self.pos])
    }
    #[inline]
    fn bump(&mut self) {
        self.pos += 1;
    }
    fn take_error(&mut self) -> Option<std::io::Error> {
        self.error.take()
    }
}

/// The tokenizer: [`Lexer::next_token`] returns tokens one by one and remembers where the
/// last one started (line and byte offset).
pub struct Lexer<S> {
    src: S,
    line: u32,
    offset: u64,
    /// Line of the start of the last token.
    pub token_line: u32,
    /// Byte offset of the start of the last token.
    pub token_offset: u64,
    scratch: Vec<u8>,
}

impl<S: ByteSource> Lexer<S> {
    /// A lexer at line `line`, byte `offset` of the input `src`.
    pub fn new(src: S, line: u32, offset: u64) -> Self {
        Lexer { src, line, offset, token_line: line, token_offset: offset, scratch: Vec::new() }
    }

    /// The current byte offset (just past the last token).
    pub fn offset(&self) -> u64 {
        self.offset
    }

    fn error(&self, message: impl Into<String>) -> StepError {
        StepError::at(self.token_line, None, message)
    }

    #[inline]
    fn peek(&mut self) -> Option<u8> {
        self.src.peek()
    }

    #[inline]
    fn bump(&mut self) -> Option<u8> {
        let b = self.src.peek()?;
        self.src.bump();
        self.offset += 1;
        if b == b'\n' {
            self.line += 1;
        }
        Some(b)
    }

    /// Skips white space and comments.
    fn skip_space(&mut self) -> Result<()> {
        loop {
            match self.peek() {
                Some(b' ' | b'\t' | b'\r' | b'\n' | 0x0c) => {
                    self.bump();
                }
                Some(b'/') => {
                    let (line, offset) = (self.line, self.offset);
                    self.bump();
                    if self.peek() != Some(b'*') {
                        self.token_line = line;
                        self.token_offset = offset;
                        return Err(self.error("unexpected '/' (comments are /* … */)"));
                    }
                    self.bump();
                    self.skip_comment(line)?;
                }
                _ => return Ok(()),
            }
        }
    }

    fn skip_comment(&mut self, start_line: u32) -> Result<()> {
        let mut star = false;
        loop {
            match self.bump() {
                None => {
                    return Err(StepError::at(start_line, None, "comment /* never closed by */"));
                }
                Some(b'/') if star => return Ok(()),
                Some(b) => star = b == b'*',
            }
        }
    }

    /// The next token.
    pub fn next_token(&mut self) -> Result<Token> {
        self.skip_space()?;
        self.token_line = self.line;
        self.token_offset = self.offset;
        let Some(b) = self.peek() else {
            if let Some(e) = self.src.take_error() {
                return Err(self.error(format!("cannot read: {e}")));
            }
            return Ok(Token::End);
        };
        let punct = match b {
            b'(' => Some(Token::Open),
            b')' => Some(Token::Close),
            b',' => Some(Token::Comma),
            b';' => Some(Token::Semicolon),
            b'=' => Some(Token::Equals),
            b'$' => Some(Token::Unset),
            b'*' => Some(Token::Derived),
            _ => None,
        };
        if let Some(t) = punct {
            self.bump();
            return Ok(t);
        }
        match b {
            b'#' => self.entity_name(),
            b'\'' => self.string(),
            b'"' => self.binary(),
            b'.' => self.enumeration(),
            b'0'..=b'9' | b'+' | b'-' => self.number(),
            b'A'..=b'Z' | b'a'..=b'z' | b'_' | b'!' => self.keyword(),
            _ => Err(self.error(format!("unexpected character {}", show_byte(b)))),
        }
    }

    /// Collects bytes while `pred` holds into the scratch buffer (bounded).
    fn take_while(&mut self, pred: impl Fn(u8) -> bool) -> Result<()> {
        self.scratch.clear();
        while let Some(b) = self.peek() {
            if !pred(b) {
                break;
            }
            if self.scratch.len() == MAX_TOKEN_BYTES {
                return Err(self.error(format!("token longer than {MAX_TOKEN_BYTES} bytes")));
            }
            self.scratch.push(b);
            self.bump();
        }
        Ok(())
    }

    fn scratch_str(&self) -> &str {
        // Only ASCII bytes reach the scratch buffer for these tokens.
        std::str::from_utf8(&self.scratch).unwrap_or("")
    }

    fn entity_name(&mut self) -> Result<Token> {
        self.bump();
        self.take_while(|b| b.is_ascii_digit())?;
        if self.scratch.is_empty() {
            return Err(self.error("expected digits after '#'"));
        }
        self.scratch_str()
            .parse::<u64>()
            .map(Token::EntityName)
            .map_err(|_| self.error(format!("entity name #{} is too large", self.scratch_str())))
    }

    fn keyword(&mut self) -> Result<Token> {
        self.take_while(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'-' || b == b'!')?;
        Ok(Token::Keyword(self.scratch_str().to_string()))
    }

    fn enumeration(&mut self) -> Result<Token> {
        self.bump();
        self.take_while(|b| b.is_ascii_alphanumeric() || b == b'_')?;
        let name = self.scratch_str().to_string();
        if self.peek() != Some(b'.') || name.is_empty() {
            return Err(self.error(format!("enumeration .{name} not closed by '.'")));
        }
        self.bump();
        Ok(Token::Enumeration(name))
    }

    fn binary(&mut self) -> Result<Token> {
        self.bump();
        self.take_while(|b| b.is_ascii_hexdigit())?;
        let hex = self.scratch_str().to_string();
        if self.peek() != Some(b'"') {
            return Err(self.error("binary \"…\" not closed by '\"' (only hex digits may stand inside)"));
        }
        self.bump();
        Ok(Token::Binary(hex))
    }

    fn number(&mut self) -> Result<Token> {
        self.take_while(|b| b.is_ascii_digit() || matches!(b, b'+' | b'-' | b'.' | b'E' | b'e'))?;
        let text = self.scratch_str();
        let is_real = text.contains('.');
        let valid = number_syntax_ok(text.as_bytes(), is_real);
        if !valid {
            return Err(self.error(format!("malformed number \"{text}\"")));
        }
        if is_real {
            let x: f64 = text.parse().map_err(|_| self.error(format!("malformed real \"{text}\"")))?;
            if !x.is_finite() {
                return Err(self.error(format!("real \"{text}\" is out of range")));
            }
            Ok(Token::Real(x))
        } else {
            text.parse::<i64>()
                .map(Token::Integer)
                .map_err(|_| self.error(format!("integer \"{text}\" is out of range")))
        }
    }

    fn string(&mut self) -> Result<Token> {
        let start_line = self.line;
        self.bump();
        self.scratch.clear();
        loop {
            match self.bump() {
                None => return Err(StepError::at(start_line, None, "string never closed by '")),
                Some(b'\'') => {
                    if self.peek() == Some(b'\'') {
                        self.bump();
                        self.scratch.push(b'\'');
                    } else {
                        break;
                    }
                }
                Some(b'\n' | b'\r') => {} // line breaks inside strings are not part of them
                Some(b) => {
                    if self.scratch.len() == MAX_TOKEN_BYTES {
                        return Err(self.error(format!("string longer than {MAX_TOKEN_BYTES} bytes")));
                    }
                    self.scratch.push(b);
                }
            }
        }
        decode_string(&self.scratch).map(Token::String).map_err(|m| StepError::at(start_line, None, m))
    }
}

/// Whether `text` is `[+-]digits` (integer) or `[+-]digits.digits*[E[+-]digits]` (real).
fn number_syntax_ok(text: &[u8], real: bool) -> bool {
    let mut i = 0;
    if matches!(text.first(), Some(b'+' | b'-')) {
        i = 1;
    }
    let digits = |i: &mut usize| {
        let s = *i;
        while *i < text.len() && text[*i].is_ascii_digit() {
            *i += 1;
        }
        *i > s
    };
    if !digits(&mut i) {
        return false;
    }
    if !real {
        return i == text.len();
    }
    if text.get(i) != Some(&b'.') {
        return false;
    }
    i += 1;
    digits(&mut i);
    if matches!(text.get(i), Some(b'E' | b'e')) {
        i += 1;
        if matches!(text.get(i), Some(b'+' | b'-')) {
            i += 1;
        }
        if !digits(&mut i) {
            return false;
        }
    }
    i == text.len()
}

fn show_byte(b: u8) -> String {
    if b.is_ascii_graphic() { format!("'{}'", b as char) } else { format!("byte 0x{b:02X}") }
}

/// Decodes the body of a string (between the apostrophes, `''` already undone): the
/// control directives of ISO 10303-21 §6.4.3 and UTF-8 text. A string that is not UTF-8
/// holds raw 8-bit bytes, which CAD systems write for names in their user's code page
/// against the standard: they are read as ISO 8859-1, the standard's default page (a name
/// may show the wrong accented letter, but the file opens).
pub fn decode_string(raw: &[u8]) -> std::result::Result<String, String> {
    let latin1: String;
    let text = match std::str::from_utf8(raw) {
        Ok(text) => text,
        Err(_) => {
            latin1 = raw.iter().map(|&b| char::from(b)).collect();
            &latin1
        }
    };
    if !text.contains('\\') {
        return Ok(text.to_string());
    }
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < b.len() {
        if b[i] != b'\\' {
            let ch = text[i..].chars().next().expect("in bounds");
            out.push(ch);
            i += ch.len_utf8();
            continue;
        }
        let rest = &b[i..];
        if rest.starts_with(b"\\\\") {
            out.push('\\');
            i += 2;
        } else if rest.starts_with(b"\\S\\") && rest.len() > 3 {
            out.push(char::from(rest[3].wrapping_add(128)));
            i += 4;
        } else if rest.len() >= 4 && rest[1] == b'P' && rest[3] == b'\\' {
            i += 4; // code page switch: ISO 8859-1 is the only page decoded
        } else if rest.starts_with(b"\\X\\") && rest.len() >= 5 {
            out.push(char::from(hex_value(&rest[3..5])? as u8));
            i += 5;
        } else if rest.starts_with(b"\\X2\\") || rest.starts_with(b"\\X4\\") {
            let width = if rest[2] == b'2' { 4 } else { 8 };
            // The end marker is looked for after the start marker: in `\X2\X0\` they share a backslash.
            let end = 4 + find(&rest[4..], b"\\X0\\").ok_or("\\X2\\ or \\X4\\ run not ended by \\X0\\")?;
            let hex = &rest[4..end];
            if hex.len() % width != 0 {
                return Err(format!(
                    "\\X{}\\ run has {} hex digits, not a multiple of {width}",
                    rest[2] as char,
                    hex.len()
                ));
            }
            let units: Vec<u32> = hex.chunks(width).map(hex_value).collect::<std::result::Result<_, _>>()?;
            if width == 4 {
                let u16s: Vec<u16> = units.iter().map(|&u| u as u16).collect();
                out.push_str(&String::from_utf16(&u16s).map_err(|_| "invalid UTF-16 in \\X2\\ run".to_string())?);
            } else {
                for u in units {
                    out.push(char::from_u32(u).ok_or_else(|| format!("invalid code point {u:X} in \\X4\\ run"))?);
                }
            }
            i += end + 4;
        } else {
            return Err(format!(
                "unknown escape in string near \"{}\"",
                String::from_utf8_lossy(&rest[..rest.len().min(6)])
            ));
        }
    }
    Ok(out)
}

fn find(hay: &[u8], needle: &[u8]) -> Option<usize> {
    hay.windows(needle.len()).position(|w| w == needle)
}

fn hex_value(digits: &[u8]) -> std::result::Result<u32, String> {
    let s = std::str::from_utf8(digits).map_err(|_| "bad hex digits in string".to_string())?;
    u32::from_str_radix(s, 16).map_err(|_| format!("bad hex digits \"{s}\" in string"))
}

/// Encodes a string for a Part 21 file: `'` doubled, `\` doubled, characters outside
/// printable ASCII as `\X2\…\X0\` (UTF-16) runs, so any text round-trips.
pub fn encode_string(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('\'');
    let mut run: Vec<u16> = Vec::new();
    let flush = |out: &mut String, run: &mut Vec<u16>| {
        if !run.is_empty() {
            out.push_str("\\X2\\");
            for u in run.drain(..) {
                out.push_str(&format!("{u:04X}"));
            }
            out.push_str("\\X0\\");
        }
    };
    for ch in text.chars() {
        if (' '..='~').contains(&ch) {
            flush(&mut out, &mut run);
            match ch {
                '\'' => out.push_str("''"),
                '\\' => out.push_str("\\\\"),
                c => out.push(c),
            }
        } else {
            let mut buf = [0u16; 2];
            run.extend_from_slice(ch.encode_utf16(&mut buf));
        }
    }
    flush(&mut out, &mut run);
    out.push('\'');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tokens(text: &str) -> Vec<Token> {
        let mut lx = Lexer::new(SliceSource::new(text.as_bytes()), 1, 0);
        let mut out = Vec::new();
        loop {
            let t = lx.next_token().unwrap();
            if t == Token::End {
                return out;
            }
            out.push(t);
        }
    }

    #[test]
    fn numbers_strings_enumerations() {
        assert_eq!(
            tokens("#12=A(1.,-2.5E-07,3,'it''s',.T.,$,*,\"0F\") /* c */ ;"),
            vec![
                Token::EntityName(12),
                Token::Equals,
                Token::Keyword("A".into()),
                Token::Open,
                Token::Real(1.0),
                Token::Comma,
                Token::Real(-2.5e-7),
                Token::Comma,
                Token::Integer(3),
                Token::Comma,
                Token::String("it's".into()),
                Token::Comma,
                Token::Enumeration("T".into()),
                Token::Comma,
                Token::Unset,
                Token::Comma,
                Token::Derived,
                Token::Comma,
                Token::Binary("0F".into()),
                Token::Close,
                Token::Semicolon,
            ]
        );
    }

    #[test]
    fn string_escapes_decode() {
        assert_eq!(decode_string(b"a\\\\b").unwrap(), "a\\b");
        assert_eq!(decode_string(b"\\X\\E9t\\X\\E9").unwrap(), "été");
        assert_eq!(decode_string(b"\\X2\\03B103B2\\X0\\!").unwrap(), "αβ!");
        assert_eq!(decode_string(b"\\X4\\0001F600\\X0\\").unwrap(), "😀");
        assert_eq!(decode_string(b"\\S\\i").unwrap(), "é");
        assert!(decode_string(b"\\Q\\").is_err());
        // Start and end markers sharing a backslash: an empty run, not a slice out of order.
        assert_eq!(decode_string(b"\\X2\\\\X0\\").unwrap(), "");
        assert!(decode_string(b"\\X2\\X0\\").is_err());
    }

    #[test]
    fn encoded_strings_round_trip() {
        for s in ["", "plain", "it's a \\ path", "αβ😀 mixed ' \\"] {
            let enc = encode_string(s);
            assert_eq!(tokens(&enc), vec![Token::String(s.to_string())], "{enc}");
        }
    }

    #[test]
    fn malformed_tokens_name_their_line() {
        let mut lx = Lexer::new(SliceSource::new(b"\n\n 1.2.3"), 1, 0);
        let e = lx.next_token().unwrap_err();
        assert_eq!(e.location.line, 3);
        assert!(e.message.contains("1.2.3"), "{e}");
        let mut lx = Lexer::new(SliceSource::new(b"\n'open"), 1, 0);
        assert_eq!(lx.next_token().unwrap_err().location.line, 2);
        let mut lx = Lexer::new(SliceSource::new(b"/* never"), 1, 0);
        assert!(lx.next_token().unwrap_err().message.contains("comment"));
    }
}
