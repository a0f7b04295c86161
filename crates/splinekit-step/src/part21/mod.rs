//! ISO 10303-21 ("Part 21", the STEP clear-text encoding): tokenizer, record grammar, a
//! checked random-access view of a file, and a writer.
//!
//! Why our own reader: ruststep 0.4 (the parser truck uses) builds here, but parses a
//! whole `&str` into an owned tree of every record (the file and its tree in memory at
//! once) and reports nom positions rather than the line and instance of a fault. This
//! one streams, keeps an index of ~32 bytes per instance, and names line and `#id`.

pub mod file;
pub mod lexer;
pub mod parser;
pub mod writer;

pub use file::{Header, StepFile};
pub use parser::{Instance, Param, Record};
pub use writer::Part21Writer;
