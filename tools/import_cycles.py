#!/usr/bin/env python3
"""Lists import cycles between files inside each crate.

A file depends on another file of its crate when its code (comments, doc links and string
literals do not count, nor `#[cfg(test)] mod … { … }` blocks) names an item of it:
`use crate::…`, `use super::…`, `use self::…` trees (braces expanded) and `crate::…` /
`super::…` / `self::…` paths in expressions. A path is resolved to the longest prefix that
is a module file; when the next segment is an item that module only re-exports
(`pub use x::Item`), the dependency is on the file that defines it, followed through any
chain of re-exports. A file and its ancestors and descendants (a mod.rs or lib.rs and the
files it declares) are not dependencies of each other, and a path through an ancestor
(`crate::Item`, `super::Item`) is not counted, even when the ancestor re-exports the item
from a sibling; `--strict` follows those re-exports too (so `crate::Renderer` counts as
renderer.rs), which also shows traits whose provided methods call into the algorithm
files that take the trait. Cycles are the strongly connected components of more than one
file; each is printed with the edges inside it and the line that makes each edge.

Usage:
    tools/import_cycles.py                 # every crate under crates/
    tools/import_cycles.py crates/a crates/b
    tools/import_cycles.py --quiet …       # components only, no edges
    tools/import_cycles.py --strict …      # follow re-exports through ancestors
Exit status 0 always; the last line is `cycles: N`.
"""
import os
import re
import sys


def module_files(src):
    """Map of module path (tuple) -> file, for src/ of one crate."""
    mods = {}
    for root, _, files in os.walk(src):
        for f in files:
            if not f.endswith(".rs"):
                continue
            rel = os.path.relpath(os.path.join(root, f), src)[:-3].split(os.sep)
            if rel[-1] in ("lib", "main") and len(rel) == 1:
                path = ()
            elif rel[-1] == "mod":
                path = tuple(rel[:-1])
            else:
                path = tuple(rel)
            mods[path] = os.path.join(root, f)
    return mods


def strip_code(text):
    """The text with comments, string and char literals blanked (line numbers kept) and
    `#[cfg(test)] mod name { … }` blocks removed."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            i = j
        elif text.startswith("/*", i):
            depth, j = 1, i + 2
            while j < n and depth:
                if text.startswith("/*", j):
                    depth, j = depth + 1, j + 2
                elif text.startswith("*/", j):
                    depth, j = depth - 1, j + 2
                else:
                    j += 1
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif c == "r" and re.match(r'r#*"', text[i:i + 8]) and not (i and (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'r(#*)"', text[i:])
            end = text.find('"' + m.group(1), i + len(m.group(0)))
            end = n if end < 0 else end + 1 + len(m.group(1))
            out.append('""' + "\n" * text.count("\n", i, end))
            i = end
        elif c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            out.append('""' + "\n" * text.count("\n", i, j))
            i = j + 1
        elif c == "'" and re.match(r"'(\\.|[^\\'])'", text[i:i + 4]):
            m = re.match(r"'(\\.|[^\\'])'", text[i:])
            out.append("' '")
            i += len(m.group(0))
        else:
            out.append(c)
            i += 1
    code = "".join(out)
    while True:
        m = re.search(r"#\[cfg\(test\)\]\s*(pub(\([^)]*\))?\s+)?mod\s+\w+\s*\{", code)
        if not m:
            return code
        depth, j = 1, m.end()
        while j < len(code) and depth:
            depth += {"{": 1, "}": -1}.get(code[j], 0)
            j += 1
        code = code[: m.start()] + "\n" * code.count("\n", m.start(), j) + code[j:]


def use_paths(tree):
    """Expands one use tree (`a::{b, c::{d as e, *}}`) into (path, alias) pairs."""
    tokens = re.findall(r"::|\{|\}|,|\*|\w+", tree)
    pos = [0]

    def parse(prefix):
        found = []
        while pos[0] < len(tokens):
            t = tokens[pos[0]]
            if t == "{":
                pos[0] += 1
                while tokens[pos[0]] != "}":
                    found += parse(list(prefix))
                    if tokens[pos[0]] == ",":
                        pos[0] += 1
                pos[0] += 1
                return found
            if t in (",", "}"):
                break
            pos[0] += 1
            if t == "::":
                continue
            if t == "as":
                alias = tokens[pos[0]]
                pos[0] += 1
                return [(prefix, alias)]
            prefix = prefix + [t]
        if prefix:
            last = prefix[-1]
            if last == "self":
                prefix = prefix[:-1]
                last = prefix[-1] if prefix else ""
            found.append((prefix, last))
        return found

    return parse([])


USE = re.compile(r"\b(pub(?:\([^)]*\))?\s+)?use\s+([^;]*);")
PATH = re.compile(r"(?<![\w:])((?:crate|super|self)(?:::\w+)+)")


def related(a, b):
    """Whether module a is module b, an ancestor or a descendant of it."""
    n = min(len(a), len(b))
    return a[:n] == b[:n]


class Crate:
    def __init__(self, src, strict=False):
        self.strict = strict
        self.mods = module_files(src)
        self.code = {p: strip_code(open(f).read()) for p, f in self.mods.items()}
        # Per module: name -> absolute path its `pub use` re-exports (item path).
        self.reexports = {p: {} for p in self.mods}
        self.defines = {p: set(re.findall(
            r"\b(?:fn|struct|enum|trait|type|const|static|union|macro_rules!)\s+(\w+)", c)) for p, c in self.code.items()}
        for p, c in self.code.items():
            for m in USE.finditer(c):
                if not m.group(1):
                    continue
                for path, alias in use_paths(m.group(2)):
                    absolute = self.absolute(p, path)
                    if absolute is not None and alias not in ("*", "self"):
                        self.reexports[p][alias] = absolute

    def directory(self, path):
        """Whether the module's file is a directory module (lib.rs, main.rs, mod.rs)."""
        return os.path.basename(self.mods[path]) in ("lib.rs", "main.rs", "mod.rs")

    def absolute(self, here, parts):
        """The absolute path (tuple) named by `parts` written in module `here`, or None for
        an external crate."""
        if not parts:
            return None
        base = here if self.directory(here) else here[:-1]
        head = parts[0]
        if head == "crate":
            return tuple(parts[1:])
        if head in ("super", "self"):
            base = here
            while parts and parts[0] in ("super", "self"):
                if parts[0] == "super":
                    base = base[:-1]
                parts = parts[1:]
            return base + tuple(parts)
        if tuple(base) + (head,) in self.mods or (not self.directory(here) and here + (head,) in self.mods):
            root = here if here + (head,) in self.mods else base
            return tuple(root) + tuple(parts)
        return None

    def file_of(self, full, seen=()):
        """The module file that defines the item at absolute path `full`."""
        for n in range(len(full), -1, -1):
            if full[:n] in self.mods:
                module, rest = full[:n], full[n:]
                break
        else:
            return None
        if rest and rest[0] not in self.defines[module] and rest[0] in self.reexports[module]:
            target = self.reexports[module][rest[0]] + rest[1:]
            if target not in seen and target != full:
                found = self.file_of(target, seen + (full,))
                if found is not None:
                    return found
        return module

    def deps(self, path):
        """{target module: first line naming it} for one file."""
        code = self.code[path]
        named = []
        uses = []
        for m in USE.finditer(code):
            line = code.count("\n", 0, m.start()) + 1
            uses.append((m.start(), m.end()))
            for parts, _ in use_paths(m.group(2)):
                named.append((parts, line))
        for m in PATH.finditer(code):
            # A `use` statement's paths are its expanded trees above; the bare prefix of a
            # braced tree (`crate::a::{B, C}` → `crate::a`) names no item of its own.
            if any(a <= m.start() < b for a, b in uses):
                continue
            named.append((m.group(1).split("::"), code.count("\n", 0, m.start()) + 1))
        out = {}
        for parts, line in named:
            full = self.absolute(path, parts)
            if full is None:
                continue
            if not self.strict:
                module = next((full[:n] for n in range(len(full), -1, -1) if full[:n] in self.mods), None)
                if module is not None and related(module, path):
                    continue
            target = self.file_of(full)
            if target is None or related(target, path):
                continue
            out.setdefault(target, line)
        return out


def components(graph):
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    sys.setrecursionlimit(10000)
    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def main():
    args = [a for a in sys.argv[1:] if a not in ("--quiet", "--strict")]
    quiet = "--quiet" in sys.argv[1:]
    strict = "--strict" in sys.argv[1:]
    if not args:
        args = [os.path.join("crates", n) for n in sorted(os.listdir("crates"))]
    total = 0
    for crate in args:
        src = os.path.join(crate, "src")
        if not os.path.isdir(src):
            continue
        c = Crate(src, strict)
        graph = {p: c.deps(p) for p in c.mods}
        name = os.path.basename(os.path.normpath(crate))
        for comp in components(graph):
            total += 1
            print(f"{name}: " + " <-> ".join("/".join(p) or "lib" for p in comp))
            if quiet:
                continue
            for a in comp:
                for b, line in sorted(graph[a].items()):
                    if b in comp:
                        print(f"    {'/'.join(a) or 'lib'} -> {'/'.join(b) or 'lib'}  ({os.path.relpath(c.mods[a])}:{line})")
    print(f"cycles: {total}")


if __name__ == "__main__":
    main()
