//! Writing JSON results to standard output or a file.

use anyhow::{Result, anyhow, bail};
use serde_json::Value;

/// Fails if any number in `value` is not finite (serde_json would print it as null).
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

/// A JSON number that must be finite (NaN would become `null`).
pub fn number(v: f64, what: &str) -> Result<Value> {
    serde_json::Number::from_f64(v).map(Value::Number).ok_or_else(|| anyhow!("{what}: the result is not finite ({v})"))
}

/// Writes `value` as compact JSON plus a newline to `output` (a path) or standard output.
pub fn write_json(value: &Value, output: Option<&str>) -> Result<()> {
    let mut text = serde_json::to_string(value)?;
    text.push('\n');
    write_text(&text, output)
}

/// Writes text to `output` (a path) or standard output.
pub fn write_text(text: &str, output: Option<&str>) -> Result<()> {
    match output {
        Some(path) if path != "-" => std::fs::write(path, text).map_err(|e| anyhow!("-o: cannot write '{path}': {e}")),
        _ => {
            use std::io::Write;
            let mut out = std::io::stdout().lock();
            out.write_all(text.as_bytes())
                .and_then(|_| out.flush())
                .map_err(|e| anyhow!("cannot write standard output: {e}"))
        }
    }
}
