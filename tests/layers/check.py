#!/usr/bin/env python3
"""check.py [--table FILE] [--nm NM] [--verbose] OBJECT...

Checks the library's layers from its object files: that no module uses a
module its row of the layer table does not allow, and that only the modules
the table lets export the API define `demill_` symbols.

The table is the one under the heading "## Layers" of docs/design.md (the
default; --table FILE reads another Markdown file), so that the document and
the test cannot drift apart. It has four columns, found by their headings:

    | module | folder | may use | exports API |

- module: the module's name;
- folder: the source folder(s) of its files, e.g. `lib/physics/state/`
  (several separated by commas);
- may use: the modules whose symbols its files may use, separated by commas
  ("nothing ..." or "—" for none, "every module" for all); a module always
  uses itself;
- exports API: "yes" or "no" (anything after the word is a comment): whether
  its files may define `demill_` symbols.

Each OBJECT is one of the library's object files, as CMake names them,
.../demill_objects.dir/lib/<folders>/<file>.c.o: the part after the `.dir/`
folder, less the `.o`, is its source path, and the longest table folder it
starts with gives its module. An object in no listed folder is an error: a
new folder must be added to the table.

The symbols each object defines (global: T, D, B, R, ...) and leaves
undefined (U) are read with `nm -P -g -A`. A C name cannot contain a dot, so
everything from the first dot of a symbol is a suffix the compiler added
(target_clones' .arch_x86_64_v3, .default and .resolver, or .cold, .part.N,
.constprop.N) and is dropped. Every undefined symbol that another object of
the library defines is an arrow from the user's module to the definer's;
arrows inside a module are free.

Only what the objects link against is seen: a static inline function of a
header, or a type or macro, is compiled into its user and leaves no arrow.

Exits 0 when every arrow is allowed and every `demill_` symbol is defined
where the table allows it; 1, naming the file, the symbol and the two
modules of each, when not; 2 for a table that cannot be read, an object in
no listed folder, or an object nm cannot read. --verbose also prints the
arrows found (module -> module: number of symbol uses).
"""
import argparse
import os
import re
import subprocess
import sys

HEADING = re.compile(r"^##\s+Layers\s*$")
NONE_WORDS = ("nothing", "none", "—", "–", "-", "")
ALL_WORDS = ("every module", "all", "all modules")


class CheckError(Exception):
    pass


def cells(line):
    """The cells of a Markdown table row, without backticks and spaces."""
    row = line.strip()
    if row.startswith("|"):
        row = row[1:]
    if row.endswith("|"):
        row = row[:-1]
    return [c.replace("`", "").strip() for c in row.split("|")]


def read_table(path):
    """[(module, [folder...], may_use set or None for all, exports)] in table order."""
    try:
        with open(path, encoding="utf-8") as f:
            lines = f.read().split("\n")
    except OSError as e:
        raise CheckError(f"cannot read {path}: {e.strerror}")
    start = next((i for i, l in enumerate(lines) if HEADING.match(l)), None)
    if start is None:
        raise CheckError(f"{path}: no '## Layers' heading")
    rows = []
    for line in lines[start + 1:]:
        if line.startswith("## "):
            break
        if line.lstrip().startswith("|"):
            rows.append(cells(line))
        elif rows:
            break  # the first table ends
    if len(rows) < 3:
        raise CheckError(f"{path}: no table under '## Layers'")
    head = [h.lower() for h in rows[0]]

    def column(word):
        hits = [i for i, h in enumerate(head) if word in h]
        if len(hits) != 1:
            raise CheckError(f"{path}: the layer table needs one column headed '{word}' "
                             f"(headings: {' | '.join(rows[0])})")
        return hits[0]

    c_mod, c_dir, c_use, c_exp = (column(w) for w in ("module", "folder", "use", "export"))
    if not all(re.fullmatch(r":?-+:?", c) for c in rows[1]):
        raise CheckError(f"{path}: the layer table's second line is not a separator")
    table, names, listed = [], set(), set()
    for n, row in enumerate(rows[2:], start=1):
        if len(row) != len(head):
            raise CheckError(f"{path}: layer table row {n} has {len(row)} cells, not {len(head)}")
        name = row[c_mod]
        if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name) or name in names:
            raise CheckError(f"{path}: layer table row {n}: bad or repeated module name '{name}'")
        names.add(name)
        folders = [f.strip().rstrip("/") + "/" for f in row[c_dir].split(",") if f.strip()]
        if not folders:
            raise CheckError(f"{path}: module {name} has no folder")
        for folder in folders:
            if folder in listed:
                raise CheckError(f"{path}: folder {folder} is in two rows")
            listed.add(folder)
        use = re.sub(r"\(.*?\)", "", row[c_use]).strip().lower()
        if use in ALL_WORDS:
            may_use = None
        elif use.split(" ")[0] in NONE_WORDS:
            may_use = set()
        else:
            may_use = {u.strip() for u in re.split(r",|\band\b", use) if u.strip()}
        exports = row[c_exp].lower().split(" ")[0].strip(",.;:")
        if exports not in ("yes", "no"):
            raise CheckError(f"{path}: module {name}: exports API is '{row[c_exp]}', "
                             f"not yes or no")
        table.append((name, folders, may_use, exports == "yes"))
    for name, _, may_use, _ in table:
        unknown = sorted((may_use or set()) - names)
        if unknown:
            raise CheckError(f"{path}: module {name} may use unknown module(s) "
                             f"{', '.join(unknown)}")
    return table


def source_path(obj):
    """lib/x/y.c for .../demill_objects.dir/lib/x/y.c.o, or None."""
    parts = obj.replace(os.sep, "/").split("/")
    dirs = [i for i, p in enumerate(parts) if p.endswith(".dir")]
    if not dirs:
        return None
    rel = "/".join(parts[dirs[-1] + 1:])
    return re.sub(r"\.(o|obj)$", "", rel)


def module_of(src, table):
    """The module of the longest table folder src starts with, or None."""
    hits = [(len(folder), name) for name, folders, _, _ in table
            for folder in folders if src.startswith(folder)]
    return max(hits)[1] if hits else None


def symbols(nm, objects):
    """{object: (defined, undefined)}: the global symbols of each, suffixes dropped."""
    try:
        out = subprocess.run([nm, "-P", "-g", "-A"] + objects, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, universal_newlines=True)
    except OSError as e:
        raise CheckError(f"cannot run {nm}: {e.strerror}")
    if out.returncode != 0:
        raise CheckError(f"{nm} cannot read the objects: {out.stderr.strip()}")
    found = {obj: (set(), set()) for obj in objects}
    for line in out.stdout.split("\n"):
        obj, _, rest = line.rpartition(": ")  # "OBJECT: name type [value size]"
        fields = rest.split()
        if obj not in found or len(fields) < 2:
            continue
        name, kind = fields[0].split(".")[0], fields[1]
        if not name:
            continue  # a local label such as .LC0
        defined, undefined = found[obj]
        if kind == "U":
            undefined.add(name)
        elif kind not in ("w", "v"):  # lower-case w and v are undefined weak symbols
            defined.add(name)
    return {obj: (d, u - d) for obj, (d, u) in found.items()}


def judge(table, files):
    """(problems, {(module, module): uses}) for files [(source, module, defined, undefined)]."""
    order = [t[0] for t in table]
    rows = {t[0]: t for t in table}
    definer = {}
    for src, mod, defined, _ in files:
        for s in defined:
            definer.setdefault(s, []).append((src, mod))
    problems, arrows = [], {}
    for src, mod, defined, undefined in files:
        _, _, may_use, exports = rows[mod]
        for s in sorted(defined):
            if s.startswith("demill_") and not exports:
                problems.append(f"{src}: defines {s}, but module {mod} may not define "
                                f"demill_ symbols (only the modules whose 'exports API' is yes)")
        for s in sorted(undefined):
            for dsrc, dmod in definer.get(s, []):
                if dmod == mod:
                    continue
                arrows[(mod, dmod)] = arrows.get((mod, dmod), 0) + 1
                if may_use is not None and dmod not in may_use:
                    allowed = ", ".join(sorted(may_use, key=order.index)) or "nothing"
                    problems.append(f"{src}: uses {s} (defined in {dsrc}): {mod} -> {dmod} "
                                    f"is not allowed ({mod} may use: {allowed})")
    return problems, arrows


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(
        description="Checks the library's object files against the layer table of "
                    "docs/design.md (see the top of this file).")
    parser.add_argument("objects", nargs="+", metavar="OBJECT")
    design = os.path.normpath(os.path.join(here, "..", "..", "docs", "design.md"))
    parser.add_argument("--table", default=design,
                        help="Markdown file with the '## Layers' table (default: docs/design.md)")
    parser.add_argument("--nm", default="nm", help="the nm program (default: nm)")
    parser.add_argument("--verbose", action="store_true",
                        help="also print the arrows found, module -> module: count")
    args = parser.parse_args()

    try:
        table = read_table(args.table)
        placed, lost = [], []
        for obj in args.objects:
            src = source_path(obj)
            mod = src and module_of(src, table)
            if mod:
                placed.append((obj, src, mod))
            else:
                lost.append(src or obj)
        if lost:
            raise CheckError("\n".join(f"{src} is in no folder of the layer table "
                                       f"({args.table}); add its folder to a module's row"
                                       for src in lost))
        syms = symbols(args.nm, [obj for obj, _, _ in placed])
    except CheckError as e:
        print("\n".join(f"layers: {line}" for line in str(e).split("\n")), file=sys.stderr)
        return 2
    files = [(src, mod) + syms[obj] for obj, src, mod in placed]
    problems, arrows = judge(table, files)
    if args.verbose:
        order = [t[0] for t in table]
        print(f"layers: {len(files)} objects in {len(table)} modules; arrows (symbol uses):")
        for (a, b), n in sorted(arrows.items(), key=lambda k: (order.index(k[0][0]),
                                                                order.index(k[0][1]))):
            print(f"  {a} -> {b}: {n}")
    if problems:
        for p in problems:
            print(f"layers: {p}")
        print(f"layers: FAIL: {len(problems)} use(s) or definition(s) that the layer table "
              f"({args.table}) does not allow")
        return 1
    print(f"layers: OK: {len(files)} objects, {sum(arrows.values())} uses across modules, "
          f"all allowed by {args.table}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
