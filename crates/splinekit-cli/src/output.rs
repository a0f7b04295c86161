//! Writing results to standard output or a file.
//!
//! Large results are streamed: [`JsonOut`] writes numbers as they come (each checked to
//! be finite, since JSON has no infinity and serde_json would print `null`), through a
//! buffer, so the memory of the output does not grow with the number of values. A write
//! error, or a value that is not finite, ends the command with exit status 2. Files are
//! written through [`splinekit_scene::OutputFile`]: a regular file is replaced only when the
//! whole result is written (a failure leaves the old file as it was and removes only the
//! temporary file), and devices, FIFOs and symbolic links are written in place and never
//! removed. Standard output is held in memory up to
//! [`STDOUT_HOLD`] bytes, so a command that fails before producing that much prints
//! nothing at all (CONTRACT.md section 3); only a larger result that fails part-way is
//! left cut off mid-way (not valid JSON).

use std::io::{BufWriter, Write};

use anyhow::{Result, anyhow, bail};
use serde_json::Value;
use splinekit_scene::OutputFile;

/// Fails if any number in `value` is not finite (serde_json would print it as null),
/// naming `what` the value is and the path inside it.
pub fn check_finite(value: &Value, path: &str) -> Result<()> {
    match value {
        Value::Number(n) if n.as_f64().is_some_and(|f| !f.is_finite()) => {
            bail!("{path}: the result is not finite");
        }
        Value::Array(a) => {
            for (i, v) in a.iter().enumerate() {
                check_finite(v, &format!("{path}[{i}]"))?;
            }
        }
        Value::Object(m) => {
            for (k, v) in m {
                check_finite(v, &format!("{path}.{k}"))?;
            }
        }
        _ => {}
    }
    Ok(())
}

/// Writes `value` as compact JSON plus a newline to `output` (a path) or standard output.
pub fn write_json(value: &Value, output: Option<&str>) -> Result<()> {
    let mut text = serde_json::to_string(value)?;
    text.push('\n');
    write_bytes(text.as_bytes(), output)
}

/// Writes bytes to `output` (a path; `-` or `None` is standard output).
pub fn write_bytes(bytes: &[u8], output: Option<&str>) -> Result<()> {
    let mut out = JsonOut::create(output)?;
    out.raw(bytes)?;
    out.finish()
}

/// Bytes of standard output held back before the first write, so an error found while
/// computing a result of up to this size leaves standard output empty.
pub const STDOUT_HOLD: usize = 16 << 20;

/// Where output goes.
enum Sink {
    /// Standard output: bytes held until [`STDOUT_HOLD`] is reached or the output finishes.
    Stdout(Vec<u8>),
    File(BufWriter<OutputFile>, String),
}

/// A streaming JSON writer (see the module documentation).
pub struct JsonOut {
    sink: Option<Sink>,
    number: Vec<u8>,
}

impl JsonOut {
    /// Output to the file `output`, or to standard output for `None` or `-`.
    pub fn create(output: Option<&str>) -> Result<Self> {
        const BUFFER: usize = 1 << 16;
        let sink = match output {
            Some(path) if path != "-" => {
                let file = OutputFile::create(path).map_err(|e| anyhow!("-o: cannot write '{path}': {e}"))?;
                Sink::File(BufWriter::with_capacity(BUFFER, file), path.to_string())
            }
            _ => Sink::Stdout(Vec::with_capacity(BUFFER)),
        };
        Ok(JsonOut { sink: Some(sink), number: Vec::with_capacity(32) })
    }

    fn fail(&mut self, e: std::io::Error) -> anyhow::Error {
        match self.sink.take() {
            // Dropping the output removes its temporary file, never the target.
            Some(Sink::File(_, path)) => anyhow!("-o: cannot write '{path}': {e}"),
            _ => anyhow!("cannot write standard output: {e}"),
        }
    }

    /// Writes text as it is (punctuation, keys).
    pub fn raw(&mut self, bytes: &[u8]) -> Result<()> {
        let result = match self.sink.as_mut() {
            Some(Sink::Stdout(held)) => {
                held.extend_from_slice(bytes);
                if held.len() >= STDOUT_HOLD { write_stdout(held) } else { Ok(()) }
            }
            Some(Sink::File(w, _)) => w.write_all(bytes),
            None => return Ok(()),
        };
        result.map_err(|e| self.fail(e))
    }

    /// Writes a number in serde_json's format (shortest digits that read back exactly);
    /// a value that is not finite is an error naming `what` it is.
    pub fn number(&mut self, v: f64, what: impl FnOnce() -> String) -> Result<()> {
        if !v.is_finite() {
            self.abandon();
            bail!("{}: the result is not finite ({v}); the numbers overflow double precision", what());
        }
        let mut number = std::mem::take(&mut self.number);
        number.clear();
        serde_json::to_writer(&mut number, &v).expect("writing to memory");
        let result = self.raw(&number);
        self.number = number;
        result
    }

    /// Writes `[x, y, …]`.
    pub fn point(&mut self, p: &[f64], what: impl Fn() -> String) -> Result<()> {
        self.raw(b"[")?;
        for (i, &c) in p.iter().enumerate() {
            if i > 0 {
                self.raw(b",")?;
            }
            self.number(c, &what)?;
        }
        self.raw(b"]")
    }

    /// Drops the output after an error: a file being written is abandoned (the target left
    /// as it was), standard output still held back is never written.
    pub fn abandon(&mut self) {
        self.sink = None;
    }

    /// Flushes everything and puts a file in place; a write error here is an error too.
    pub fn finish(mut self) -> Result<()> {
        match self.sink.take() {
            Some(Sink::Stdout(mut held)) => write_stdout(&mut held)
                .and_then(|()| std::io::stdout().flush())
                .map_err(|e| anyhow!("cannot write standard output: {e}")),
            Some(Sink::File(w, path)) => w
                .into_inner()
                .map_err(|e| e.into_error())
                .and_then(OutputFile::commit)
                .map_err(|e| anyhow!("-o: cannot write '{path}': {e}")),
            None => Ok(()),
        }
    }
}

/// Writes the held bytes to standard output and empties the buffer.
fn write_stdout(held: &mut Vec<u8>) -> std::io::Result<()> {
    std::io::stdout().lock().write_all(held)?;
    held.clear();
    Ok(())
}

impl Drop for JsonOut {
    /// An output dropped before [`JsonOut::finish`] (an error on the way) is abandoned.
    fn drop(&mut self) {
        self.abandon();
    }
}
