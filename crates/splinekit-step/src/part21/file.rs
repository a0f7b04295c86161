//! A STEP file opened for random access: the header, and an index of every entity
//! instance (its `#id`, type name, line and byte range) with the instances themselves
//! parsed on demand.
//!
//! Reading streams the file once through a 64 KiB buffer, checking the whole syntax and
//! keeping ~32 bytes per instance (never the text or a parse tree of the whole file); a
//! second walk over the index checks that every reference names an instance and that
//! the references form no cycle. So memory grows with the number of instances at a
//! small constant, not with the file's bytes, and a malformed file fails with the line
//! and instance of the first fault.

use std::collections::HashMap;
use std::fs::File;
use std::io::{Read, Seek, SeekFrom};
use std::path::Path;
use std::sync::Mutex;

use crate::error::{Result, StepError};
use crate::part21::lexer::{ByteSource, Lexer, ReaderSource, SliceSource, Token};
use crate::part21::parser::{Instance, Param, Parser, Record};

/// The header section: `FILE_DESCRIPTION`, `FILE_NAME`, `FILE_SCHEMA` and any others.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Header {
    /// Every header record in order.
    pub records: Vec<Record>,
}

impl Header {
    /// The schema names of `FILE_SCHEMA` (e.g. `AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }`).
    pub fn schemas(&self) -> Vec<String> {
        let Some(r) = self.records.iter().find(|r| r.name == "FILE_SCHEMA") else {
            return Vec::new();
        };
        match r.params.first() {
            Some(Param::List(items)) => {
                items.iter().filter_map(|p| if let Param::String(s) = p { Some(s.clone()) } else { None }).collect()
            }
            _ => Vec::new(),
        }
    }
}

/// Where an instance is: its name, type, line and bytes.
#[derive(Debug, Clone, Copy)]
struct Entry {
    id: u64,
    offset: u64,
    len: u32,
    line: u32,
    type_index: u32,
}

/// The bytes of the file, to parse instances from on demand.
enum Source {
    Memory(Vec<u8>),
    File(Mutex<File>),
}

/// A parsed, checked STEP file (see the module documentation).
pub struct StepFile {
    header: Header,
    entries: Vec<Entry>,
    type_names: Vec<String>,
    source: Source,
}

impl std::fmt::Debug for StepFile {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("StepFile").field("instances", &self.entries.len()).finish()
    }
}

/// What the scan of the whole file collects.
struct Scan {
    header: Header,
    entries: Vec<Entry>,
    type_names: Vec<String>,
}

impl StepFile {
    /// Reads a file from memory.
    pub fn from_bytes(bytes: Vec<u8>) -> Result<Self> {
        let scan = scan(SliceSource::new(&bytes))?;
        StepFile::finish(scan, Source::Memory(bytes))
    }

    /// Reads everything from `reader` into memory, then as [`StepFile::from_bytes`] (for
    /// standard input; files are better opened with [`StepFile::open`]).
    pub fn from_reader(mut reader: impl Read) -> Result<Self> {
        let mut bytes = Vec::new();
        reader.read_to_end(&mut bytes)?;
        Self::from_bytes(bytes)
    }

    /// Opens a file on disk: streamed for the scan, read back by byte range on demand.
    pub fn open(path: &Path) -> Result<Self> {
        let file = File::open(path).map_err(|e| StepError::plain(format!("cannot open {}: {e}", path.display())))?;
        let scan = scan(ReaderSource::new(&file))?;
        StepFile::finish(scan, Source::File(Mutex::new(file)))
    }

    fn finish(scan: Scan, source: Source) -> Result<Self> {
        let Scan { header, mut entries, type_names } = scan;
        entries.sort_unstable_by_key(|e| (e.id, e.offset));
        if let Some(w) = entries.windows(2).find(|w| w[0].id == w[1].id) {
            let (first, second) = if w[0].offset < w[1].offset { (w[0], w[1]) } else { (w[1], w[0]) };
            return Err(StepError::at(
                second.line,
                Some(second.id),
                format!("instance #{} is defined twice (first on line {})", second.id, first.line),
            ));
        }
        let file = StepFile { header, entries, type_names, source };
        file.check_references()?;
        Ok(file)
    }

    /// The header section.
    pub fn header(&self) -> &Header {
        &self.header
    }

    /// Number of entity instances.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// Whether the data section is empty.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// Every instance name, increasing.
    pub fn ids(&self) -> impl Iterator<Item = u64> + '_ {
        self.entries.iter().map(|e| e.id)
    }

    fn entry(&self, id: u64) -> Option<&Entry> {
        self.entries.binary_search_by_key(&id, |e| e.id).ok().map(|i| &self.entries[i])
    }

    /// Whether `#id` is defined.
    pub fn contains(&self, id: u64) -> bool {
        self.entry(id).is_some()
    }

    /// The line on which `#id` starts (0 if there is no such instance).
    pub fn line_of(&self, id: u64) -> u32 {
        self.entry(id).map_or(0, |e| e.line)
    }

    /// The type name of `#id` (`(A B)` for complex instances).
    pub fn type_of(&self, id: u64) -> Option<&str> {
        self.entry(id).map(|e| self.type_names[e.type_index as usize].as_str())
    }

    /// The instances whose type name is `name`, increasing.
    pub fn ids_of_type<'a>(&'a self, name: &'a str) -> impl Iterator<Item = u64> + 'a {
        let index = self.type_names.iter().position(|n| n == name).map(|i| i as u32);
        self.entries.iter().filter(move |e| Some(e.type_index) == index).map(|e| e.id)
    }

    /// How many instances of each type name the file holds, by name.
    pub fn census(&self) -> Vec<(String, usize)> {
        let mut counts = vec![0usize; self.type_names.len()];
        for e in &self.entries {
            counts[e.type_index as usize] += 1;
        }
        let mut out: Vec<(String, usize)> =
            self.type_names.iter().cloned().zip(counts).filter(|(_, c)| *c > 0).collect();
        out.sort();
        out
    }

    /// Parses instance `#id`.
    pub fn get(&self, id: u64) -> Result<Instance> {
        let e = *self.entry(id).ok_or_else(|| StepError::plain(format!("#{id} is not defined in the file")))?;
        let parse = |bytes: &[u8]| -> Result<Instance> {
            let mut p = Parser::new(Lexer::new(SliceSource::new(bytes), e.line, e.offset));
            p.next_token()?; // the #id itself
            p.instance_body(e.id, e.line)
        };
        match &self.source {
            Source::Memory(bytes) => parse(&bytes[e.offset as usize..e.offset as usize + e.len as usize]),
            Source::File(file) => {
                let mut buf = vec![0u8; e.len as usize];
                let mut f = file.lock().unwrap_or_else(|p| p.into_inner());
                f.seek(SeekFrom::Start(e.offset))?;
                f.read_exact(&mut buf)?;
                drop(f);
                parse(&buf)
            }
        }
    }

    /// Checks that every reference names a defined instance and that no instance reaches
    /// itself through references (iterative depth-first search, one parse per instance).
    fn check_references(&self) -> Result<()> {
        #[derive(Clone, Copy, PartialEq)]
        enum Mark {
            New,
            Open,
            Done,
        }
        let mut mark = vec![Mark::New; self.entries.len()];
        let index_of = |id: u64| self.entries.binary_search_by_key(&id, |e| e.id).ok();
        for start in 0..self.entries.len() {
            if mark[start] != Mark::New {
                continue;
            }
            // Stack of (entry index, its references, next reference to follow).
            let mut stack: Vec<(usize, Vec<u64>, usize)> = Vec::new();
            let push = |i: usize, stack: &mut Vec<(usize, Vec<u64>, usize)>, mark: &mut Vec<Mark>| -> Result<()> {
                let inst = self.get(self.entries[i].id)?;
                let mut refs = Vec::new();
                for r in &inst.records {
                    r.params.iter().for_each(|p| p.for_each_reference(&mut |id| refs.push(id)));
                }
                mark[i] = Mark::Open;
                stack.push((i, refs, 0));
                Ok(())
            };
            push(start, &mut stack, &mut mark)?;
            while let Some((i, refs, next)) = stack.last_mut() {
                let Some(&target) = refs.get(*next) else {
                    mark[*i] = Mark::Done;
                    stack.pop();
                    continue;
                };
                *next += 1;
                let from = self.entries[*i];
                let Some(j) = index_of(target) else {
                    return Err(StepError::at(
                        from.line,
                        Some(from.id),
                        format!("reference to #{target}, which is not defined"),
                    ));
                };
                match mark[j] {
                    Mark::Done => {}
                    Mark::New => push(j, &mut stack, &mut mark)?,
                    Mark::Open => {
                        let pos = stack.iter().position(|(k, _, _)| *k == j).unwrap_or(0);
                        let path: Vec<String> =
                            stack[pos..].iter().map(|(k, _, _)| format!("#{}", self.entries[*k].id)).collect();
                        return Err(StepError::at(
                            from.line,
                            Some(from.id),
                            format!("reference cycle {} → #{target}", path.join(" → ")),
                        ));
                    }
                }
            }
        }
        Ok(())
    }
}

/// Streams the whole exchange structure, checking its syntax and indexing the instances.
fn scan<S: ByteSource>(src: S) -> Result<Scan> {
    let mut p = Parser::new(Lexer::new(src, 1, 0));
    p.expect_section("ISO-10303-21")?;
    p.expect_section("HEADER")?;
    let mut header = Header::default();
    loop {
        if matches!(p.peek()?, Token::Keyword(k) if k == "ENDSEC") {
            p.expect_section("ENDSEC")?;
            break;
        }
        let record = p.record()?;
        p.expect(&Token::Semicolon, "';' after a header record")?;
        header.records.push(record);
    }
    let mut entries = Vec::new();
    let mut type_names: Vec<String> = Vec::new();
    let mut type_index: HashMap<String, u32> = HashMap::new();
    let mut sections = 0;
    loop {
        match p.next_token()? {
            Token::Keyword(k) if k == "DATA" => {
                if *p.peek()? == Token::Open {
                    p.record_params_after_keyword()?;
                }
                p.expect(&Token::Semicolon, "';' after DATA")?;
                sections += 1;
                data_section(&mut p, &mut entries, &mut type_names, &mut type_index)?;
            }
            Token::Keyword(k) if k == "END-ISO-10303-21" => {
                p.expect(&Token::Semicolon, "';'")?;
                break;
            }
            Token::Keyword(k) if k == "ANCHOR" || k == "REFERENCE" || k == "SIGNATURE" => {
                return Err(StepError::at(p.token_line(), None, format!("the {k} section is not supported")));
            }
            t => {
                return Err(StepError::at(
                    p.token_line(),
                    None,
                    format!("expected DATA or END-ISO-10303-21, got {}", t.describe()),
                ));
            }
        }
    }
    if sections == 0 {
        return Err(StepError::at(p.token_line(), None, "the file has no DATA section"));
    }
    // What follows END-ISO-10303-21; is not part of the exchange structure: edition 3's
    // digital signature (CATIA writes one), mail trailers, padding. It is not read.
    Ok(Scan { header, entries, type_names })
}

fn data_section<S: ByteSource>(
    p: &mut Parser<S>,
    entries: &mut Vec<Entry>,
    type_names: &mut Vec<String>,
    type_index: &mut HashMap<String, u32>,
) -> Result<()> {
    loop {
        match p.next_token()? {
            Token::EntityName(id) => {
                let (line, offset) = (p.token_line(), p.lexer().token_offset);
                let inst = p.instance_body(id, line)?;
                let len = u32::try_from(p.lexer().offset() - offset)
                    .map_err(|_| StepError::at(line, Some(id), "instance longer than 4 GiB"))?;
                let name = inst.type_name();
                let next = type_names.len() as u32;
                let t = *type_index.entry(name.clone()).or_insert_with(|| {
                    type_names.push(name);
                    next
                });
                entries.push(Entry { id, offset, len, line, type_index: t });
            }
            Token::Keyword(k) if k == "ENDSEC" => return p.expect(&Token::Semicolon, "';' after ENDSEC"),
            t => {
                return Err(StepError::at(
                    p.token_line(),
                    None,
                    format!("expected an instance #id or ENDSEC, got {}", t.describe()),
                ));
            }
        }
    }
}

impl<S: ByteSource> Parser<S> {
    /// Skips `( parameters )` after a keyword (the parameters of `DATA(…)`).
    fn record_params_after_keyword(&mut self) -> Result<()> {
        let mut depth = 0usize;
        loop {
            match self.next_token()? {
                Token::Open => depth += 1,
                Token::Close => {
                    depth -= 1;
                    if depth == 0 {
                        return Ok(());
                    }
                }
                Token::End => return Err(StepError::at(self.token_line(), None, "DATA( … never closed")),
                _ => {}
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SMALL: &str = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('x'),'2;1');\n\
        FILE_NAME('a','',(''),(''),'','','');\nFILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n\
        #2=DIRECTION('',(0.,0.,1.));\n#1=CARTESIAN_POINT('',(1.,2.,3.));\n\
        #3=AXIS2_PLACEMENT_3D('',#1,#2,$);\nENDSEC;\nEND-ISO-10303-21;\n";

    #[test]
    fn reads_header_and_instances() {
        let f = StepFile::from_bytes(SMALL.as_bytes().to_vec()).unwrap();
        assert_eq!(f.header().schemas(), vec!["AUTOMOTIVE_DESIGN".to_string()]);
        assert_eq!(f.len(), 3);
        assert_eq!(f.ids().collect::<Vec<_>>(), vec![1, 2, 3]);
        assert_eq!(f.type_of(3), Some("AXIS2_PLACEMENT_3D"));
        assert_eq!(f.line_of(1), 9);
        let p = f.get(1).unwrap();
        assert_eq!(p.records[0].params[1], Param::List(vec![Param::Real(1.0), Param::Real(2.0), Param::Real(3.0)]));
        assert_eq!(f.census().len(), 3);
    }

    #[test]
    fn dangling_duplicate_and_cyclic_references_fail() {
        let bad = SMALL.replace("#3=AXIS2_PLACEMENT_3D('',#1,#2,$)", "#3=AXIS2_PLACEMENT_3D('',#1,#9,$)");
        let e = StepFile::from_bytes(bad.into_bytes()).unwrap_err();
        assert_eq!((e.location.line, e.location.entity), (10, Some(3)));
        assert!(e.message.contains("#9"), "{e}");
        let dup = SMALL.replace("#3=", "#2=");
        let e = StepFile::from_bytes(dup.into_bytes()).unwrap_err();
        assert!(e.message.contains("defined twice"), "{e}");
        let cyc = SMALL.replace("#2=DIRECTION('',(0.,0.,1.))", "#2=DIRECTION('',(#3))");
        let e = StepFile::from_bytes(cyc.into_bytes()).unwrap_err();
        assert!(e.message.contains("cycle"), "{e}");
    }
}
