#!/usr/bin/python3
"""docs_complete.py INCLUDE_DIR

Checks that the public headers document every function with its errors, the
rules of the API reference (docs/reference.md). Every header you add under
include/ (any *.h, found recursively, as Doxygen finds them) must follow them:

 1. The header starts with a Doxygen file comment, `/** @file demill/x.h`
    with a @brief. Without it Doxygen silently leaves everything the header
    declares out of the reference.
 2. Every DEMILL_API declaration has a doc comment `/** ... */` right before
    it (nothing but blank space in between; a `/**<` comment does not count).
 3. A function returning demill_status has an `@return` that names DEMILL_OK
    and every DEMILL_ERR_* code the function can return, by name (not "as
    for demill_x()"); the two codes every function taking a world may return
    (DEMILL_ERR_NULL_POINTER for a NULL world, DEMILL_ERR_INVALID_HANDLE for
    something that is not a live world) may be left out, as demill/common.h
    says. A function returning anything else but void has an `@return` that
    describes the value (what NULL or 0 means, if it can be returned).
 4. Every DEMILL_ERR_* named in a doc comment is a status code that exists
    (declared in the headers).
 5. Every enum has a doc comment before it, and every enum constant its own
    doc comment: `/** ... */` before it or `/**< ... */` after it on the same
    line. Doxygen 1.9 does not warn about undocumented enum values, so this
    test does.

Doxygen itself (the test api_docs_build, WARN_AS_ERROR = FAIL_ON_WARNINGS)
checks the rest: every parameter has an @param of the right name, macros and
typedefs are documented, references resolve.

Exits 1 and lists every violation as FILE:LINE: message; 0 when all hold.
"""
import os
import re
import sys

COMMENT = re.compile(r"/\*.*?\*/|//[^\n]*", re.S)
# @return's paragraph: up to the next block command or the end of the comment
RETURN = re.compile(r"[@\\]returns?\b(.*?)(?=\n\s*\*?\s*[@\\](?:param|return|retval|note|see|pre|post)\b|\Z)",
                    re.S)
ERR = re.compile(r"\bDEMILL_ERR_[A-Z0-9_]+\b")


def headers(include_dir):
    found = []
    for root, dirs, files in os.walk(include_dir):
        dirs.sort()
        found += [os.path.join(root, f) for f in sorted(files) if f.endswith(".h")]
    return found


class Header:
    def __init__(self, path, include_dir):
        self.path = path
        self.name = os.path.relpath(path, include_dir)
        with open(path, encoding="utf-8") as f:
            self.text = f.read()
        # comments: (start, end, text); code: the text with comments and
        # preprocessor lines blanked (offsets kept)
        self.comments = [(m.start(), m.end(), m.group(0)) for m in COMMENT.finditer(self.text)]
        code = list(self.text)
        for start, end, _ in self.comments:
            for i in range(start, end):
                if code[i] != "\n":
                    code[i] = " "
        self.code = "".join(code)
        self.code = re.sub(r"(?m)^[ \t]*#.*(?:\\\n.*)*$", lambda m: re.sub(r"[^\n]", " ", m.group(0)),
                           self.code)

    def line(self, offset):
        return self.text.count("\n", 0, offset) + 1

    def doc_before(self, offset):
        """The /** comment ending right before offset (only blanks between)."""
        for start, end, text in reversed(self.comments):
            if end <= offset:
                if self.text[end:offset].strip() == "" and text.startswith("/**") \
                        and not text.startswith("/**<"):
                    return text
                return None
        return None

    def doc_after_same_line(self, offset):
        """The /**< comment after offset on the same line."""
        for start, _, text in self.comments:
            if start >= offset:
                between = self.text[offset:start]
                if "\n" not in between and between.strip() in ("", ",") \
                        and text.startswith("/**<"):
                    return text
                return None
        return None


def main():
    if len(sys.argv) != 2:
        print("usage: docs_complete.py INCLUDE_DIR", file=sys.stderr)
        return 2
    include_dir = os.path.abspath(sys.argv[1])
    files = [Header(p, include_dir) for p in headers(include_dir)]
    if not files:
        print(f"FAIL: no headers under {include_dir}", file=sys.stderr)
        return 1
    problems = []

    def fail(h, offset, message):
        problems.append(f"{h.path}:{h.line(offset)}: {message}")

    # the status codes that exist
    codes = set()
    for h in files:
        codes |= set(re.findall(r"\b(DEMILL_ERR_[A-Z0-9_]+)\s*=", h.code))

    functions = constants = 0
    for h in files:
        # 1. the file comment
        first = h.comments[0] if h.comments else None
        if not first or h.text[:first[0]].strip() or not re.match(r"/\*\*\s*[@\\]file\b", first[2]):
            fail(h, 0, "the header does not start with a /** @file ... */ comment")
        elif not re.search(r"[@\\]brief\b", first[2]):
            fail(h, 0, "the @file comment has no @brief")

        # 4. only existing status codes are named
        for start, _, text in h.comments:
            for m in ERR.finditer(text):
                if m.group(0) not in codes:
                    fail(h, start + m.start(), f"{m.group(0)} is not a status code")

        # 2. and 3. functions
        for m in re.finditer(r"\bDEMILL_API\b([^;{}]*?)\b(\w+)\s*\(", h.code):
            functions += 1
            ret, name = " ".join(m.group(1).split()), m.group(2)
            doc = h.doc_before(m.start())
            if doc is None:
                fail(h, m.start(), f"{name}: no /** doc comment right before the declaration")
                continue
            returns = RETURN.findall(doc)
            text = " ".join(" ".join(returns).replace("*/", "").replace("*", " ").split())
            if ret == "void":
                continue
            if not returns or not text:
                fail(h, m.start(), f"{name} returns {ret} but its comment has no @return describing it")
            elif ret == "demill_status":
                if not re.search(r"\bDEMILL_OK\b", text):
                    fail(h, m.start(), f"{name}: @return does not name DEMILL_OK")
                if not ERR.search(text):
                    fail(h, m.start(), f"{name}: @return names no DEMILL_ERR_* code; "
                         "list every error by name")

        # 5. enums and their constants
        for m in re.finditer(r"\benum\b\s*\w*\s*\{([^}]*)\}", h.code):
            if h.doc_before(m.start()) is None and \
                    h.doc_before(h.code.rfind("typedef", 0, m.start())) is None:
                fail(h, m.start(), "enum without a /** doc comment before it")
            body = m.start(1)
            for c in re.finditer(r"\b(DEMILL_[A-Z0-9_]+)\b[^,]*,?", m.group(1)):
                constants += 1
                start, end = body + c.start(), body + c.end()
                # the constant's own text ends at the comma or at the last
                # non-blank character before the closing brace
                end = body + c.start() + len(c.group(0).rstrip())
                if h.doc_before(start) is None and h.doc_after_same_line(end) is None:
                    fail(h, start, f"{c.group(1)}: no doc comment (/** before it or /**< after it)")

    for p in problems:
        print(p, file=sys.stderr)
    if problems:
        print(f"docs_complete: {len(problems)} problem(s) in {len(files)} headers "
              "(the rules are at the top of tests/api/docs_complete.py)", file=sys.stderr)
        return 1
    print(f"docs_complete: {len(files)} headers, {functions} functions, "
          f"{constants} enum constants documented")
    return 0


if __name__ == "__main__":
    sys.exit(main())
