#!/usr/bin/env python3
"""selftest.py CC [--nm NM]

Shows that tests/layers/check.py fails when it should and passes when it
should. It compiles a few one-function C files with CC into a temporary
folder, at the paths CMake gives the library's objects
(CMakeFiles/demill_objects.dir/lib/<folders>/<file>.c.o), writes a small
layer table, and runs check.py on chosen sets of them:

  1. allowed: world and physics call base       -> exit 0
  2. upwards: base calls a function of world    -> exit 1, names the symbol
                                                   and "base -> world"
  3. nested folders: lib/physics/state/ is its own module, below
     lib/physics/; a file there calling physics -> exit 1, "state -> physics"
     (the longest folder decides)
  4. physics defines demill_leak                -> exit 1, names it
  5. an object in lib/extra/, no table folder   -> exit 2, names the file
  6. (compilers with target_clones) physics defines demill_cloned in three
     versions: one failure naming demill_cloned, without GCC's suffixes

Each expectation follows from the table below and the C sources, not from
check.py. Exits 0 when all cases behave so, 1 otherwise.
"""
import os
import shutil
import subprocess
import sys
import tempfile

TABLE = """# A layer table for the self-test

## Layers

| Module  | Folder               | May use (symbols defined in) | Exports API |
|:--------|----------------------|------------------------------|-------------|
| base    | `lib/base/`          | —                            | yes (status texts) |
| state   | `lib/physics/state/` | `base`                       | no |
| physics | `lib/physics/`       | base, state                  | no |
| world   | `lib/world/`         | every module                 | yes |

## After the table
"""

SOURCES = {
    "lib/base/a.c": "int dm_base_twice(int x) { return 2 * x; }\n",
    "lib/base/up.c": "int dm_world_answer(void);\n"
                     "int dm_base_up(void) { return dm_world_answer(); }\n",
    "lib/world/b.c": "int dm_base_twice(int x);\n"
                     "int dm_world_answer(void) { return dm_base_twice(21); }\n"
                     "int demill_answer(void) { return dm_world_answer(); }\n",
    "lib/physics/p.c": "int dm_base_twice(int x);\n"
                       "int dm_physics_thrice(int x) { return dm_base_twice(x) + x; }\n",
    "lib/physics/state/s.c": "int dm_physics_thrice(int x);\n"
                             "int dm_state_nine(void) { return dm_physics_thrice(3); }\n",
    "lib/physics/leak.c": "int demill_leak(void) { return 1; }\n",
}
CLONES = ("lib/physics/clone.c",
          '__attribute__((target_clones("arch=x86-64-v3", "default")))\n'
          "void demill_cloned(double *x, int n) { for (int i = 0; i < n; i++) x[i] *= 2; }\n")


def main():
    args = sys.argv[1:]
    nm = []
    if len(args) == 3 and args[1] == "--nm":
        nm = ["--nm", args[2]]
    elif len(args) != 1:
        print("usage: selftest.py CC [--nm NM]", file=sys.stderr)
        return 2
    cc = args[0]
    check = os.path.join(os.path.dirname(os.path.abspath(__file__)), "check.py")
    tmp = tempfile.mkdtemp(prefix="demill-layers-")
    try:
        return run(cc, nm, check, tmp)
    finally:
        shutil.rmtree(tmp)


def run(cc, nm, check, tmp):
    table = os.path.join(tmp, "design.md")
    with open(table, "w", encoding="utf-8") as f:
        f.write(TABLE)
    objdir = os.path.join(tmp, "CMakeFiles", "demill_objects.dir")

    def compile_c(src, text):
        """The object's path, or None and the compiler's complaint."""
        path = os.path.join(tmp, "src", src)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        o = os.path.join(objdir, src + ".o")
        os.makedirs(os.path.dirname(o), exist_ok=True)
        out = subprocess.run([cc, "-std=c11", "-O2", "-fPIC", "-fvisibility=hidden", "-c",
                              path, "-o", o], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, universal_newlines=True)
        return (o, None) if out.returncode == 0 else (None, out.stdout)

    obj = {}
    for src, text in SOURCES.items():
        obj[src], complaint = compile_c(src, text)
        if complaint is not None:
            print(f"FAIL: {cc} cannot compile {src}:\n{complaint}")
            return 1
    extra = os.path.join(objdir, "lib", "extra", "c.c.o")
    os.makedirs(os.path.dirname(extra))
    shutil.copy(obj["lib/base/a.c"], extra)
    obj["lib/extra/c.c"] = extra
    obj[CLONES[0]], _ = compile_c(*CLONES)

    # (name, sources, exit status, texts the output has, has once, has not)
    cases = [
        ("allowed arrows", ["lib/base/a.c", "lib/world/b.c", "lib/physics/p.c"], 0,
         ["OK"], [], []),
        ("base calls world", ["lib/base/a.c", "lib/base/up.c", "lib/world/b.c"], 1,
         ["lib/base/up.c", "dm_world_answer", "base -> world"], [], []),
        ("longest folder decides",
         ["lib/base/a.c", "lib/physics/p.c", "lib/physics/state/s.c"], 1,
         ["lib/physics/state/s.c", "dm_physics_thrice", "state -> physics"], [], []),
        ("demill_ symbol in physics", ["lib/base/a.c", "lib/physics/leak.c"], 1,
         ["lib/physics/leak.c", "demill_leak"], [], []),
        ("object in no table folder", ["lib/base/a.c", "lib/extra/c.c"], 2,
         ["lib/extra/c.c"], [], []),
    ]
    if obj[CLONES[0]]:
        cases.append(("target_clones suffixes", ["lib/base/a.c", CLONES[0]], 1,
                      [], ["defines demill_cloned,"], ["demill_cloned."]))
    failed = 0
    for name, srcs, want_rc, has, once, has_not in cases:
        out = subprocess.run([sys.executable, check, "--table", table] + nm +
                             [obj[s] for s in srcs],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             universal_newlines=True)
        text = out.stdout
        bad = [f"exit {out.returncode}, not {want_rc}"] if out.returncode != want_rc else []
        bad += [f"no '{t}' in the output" for t in has if t not in text]
        bad += [f"'{t}' {text.count(t)} times, not once" for t in once if text.count(t) != 1]
        bad += [f"'{t}' in the output" for t in has_not if t in text]
        if bad:
            failed += 1
            print(f"FAIL: {name}: {'; '.join(bad)}; check.py said:\n{text}")
        else:
            print(f"ok: {name} (exit {out.returncode})")
    if not obj[CLONES[0]]:
        print(f"(no target_clones case: {cc} does not compile it)")
    print(f"layers_selftest: {len(cases) - failed} of {len(cases)} cases as expected")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
