#!/usr/bin/env python3
"""Counts import cycles between files inside each crate of crates/.

A file depends on another file of its crate when it names it in a `use crate::…`,
`use super::…` or `crate::…::` path (the longest prefix of the path that is a module file
counts). Cycles are the strongly connected components of more than one file; the figure
printed per crate is the number of such components, and every component is listed.

Usage: tools/import_cycles.py [CRATES_DIR]   (default: crates)
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


PATH = re.compile(r"\b(crate|super)((?:::\w+)+)")
USE_GROUP = re.compile(r"\buse\s+(crate|super)((?:::\w+)*)::\{([^;]*)\};", re.S)


def strip_comments(text):
    text = re.sub(r"//[^\n]*", "", text)
    return re.sub(r"/\*.*?\*/", "", text, flags=re.S)


def resolve(mods, here, head, parts):
    if head == "crate":
        base = ()
    else:
        base = here[:-1] if here else ()
        while parts and parts[0] == "super":
            base = base[:-1]
            parts = parts[1:]
    full = base + tuple(parts)
    for n in range(len(full), 0, -1):
        if full[:n] in mods:
            return full[:n]
    return None


def deps(mods, path, file):
    text = strip_comments(open(file).read())
    # A file that is a directory module (mod.rs) is its own parent for `super`.
    here = path if not file.endswith("mod.rs") and not file.endswith("lib.rs") else path + ("_",)
    out = set()
    for m in USE_GROUP.finditer(text):
        prefix = [p for p in m.group(2).split("::") if p]
        for item in re.split(r",(?![^{]*\})", m.group(3)):
            names = [p for p in re.split(r"::|\{", item.strip()) if p and re.match(r"^\w+$", p)]
            target = resolve(mods, here, m.group(1), prefix + names[:2])
            if target is not None:
                out.add(target)
    for m in PATH.finditer(text):
        parts = [p for p in m.group(2).split("::") if p]
        target = resolve(mods, here, m.group(1), parts)
        if target is not None:
            out.add(target)
    out.discard(path)
    # Parents (mod.rs/lib.rs declaring modules) are not dependencies on their children.
    return {t for t in out if t != () and not (len(t) < len(path) and path[: len(t)] == t)}


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
    for v in graph:
        if v not in index:
            visit(v)
    return out


def main():
    crates = sys.argv[1] if len(sys.argv) > 1 else "crates"
    total = 0
    for name in sorted(os.listdir(crates)):
        src = os.path.join(crates, name, "src")
        if not os.path.isdir(src):
            continue
        mods = module_files(src)
        graph = {p: deps(mods, p, f) for p, f in mods.items()}
        comps = components(graph)
        total += len(comps)
        for c in comps:
            print(f"{name}: " + " <-> ".join("/".join(p) or "lib" for p in c))
    print(f"cycles: {total}")


if __name__ == "__main__":
    main()
