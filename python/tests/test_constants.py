"""The binding's constants and prototypes against the C headers: every
``DEMILL_... = N`` of include/demill/*.h is a Python enum member of the same
value and the other way round, and every ``DEMILL_API`` function has a
ctypes prototype of the same arity that the package uses."""

import re
import unittest

from helpers import PYTHON_DIR, REPO

import demill
from demill import _lib
from demill.constants import C_PREFIXES, Status, c_name
from demill.errors import ERRORS, Error

HEADERS = sorted((REPO / "include").rglob("*.h"))


def header_text():
    """The headers without comments."""
    text = "\n".join(h.read_text() for h in HEADERS)
    return re.sub(r"/\*.*?\*/", " ", text, flags=re.S)


def header_constants():
    """{name: value} of every enum constant and numeric #define."""
    text = header_text()
    consts = {m[1]: int(m[2]) for m in re.finditer(r"\b(DEMILL_\w+)\s*=\s*(\d+)u?\b", text)}
    defines = {m[1]: int(m[2]) for m in re.finditer(r"#define\s+(DEMILL_\w+)\s+(\d+)\s*$",
                                                      text, flags=re.M)}
    return consts, defines


def header_functions():
    """{name: number of parameters} of every DEMILL_API function."""
    text = re.sub(r"\s+", " ", header_text())
    funcs = {}
    for m in re.finditer(r"DEMILL_API [^;{}()]*?\b(demill_\w+)\s*\(([^;]*?)\)\s*;", text):
        params = m[2].strip()
        funcs[m[1]] = 0 if params in ("", "void") else params.count(",") + 1
    return funcs


class Constants(unittest.TestCase):
    def test_every_header_constant_is_in_python_with_its_value(self):
        consts, _ = header_constants()
        self.assertGreater(len(consts), 150)
        python = {c_name(m): int(m) for enum in C_PREFIXES for m in enum}
        for name, value in consts.items():
            with self.subTest(name=name):
                self.assertIn(name, python, "missing in demill/constants.py")
                self.assertEqual(python[name], value)
        self.assertEqual(set(python) - set(consts), set(), "not in the headers")

    def test_version_macros(self):
        _, defines = header_constants()
        for name in ("VERSION_MAJOR", "VERSION_MINOR", "VERSION_PATCH"):
            self.assertEqual(getattr(demill, name), defines["DEMILL_" + name])
        string = re.search(r'#define DEMILL_VERSION_STRING "([^"]+)"', header_text())[1]
        self.assertEqual(demill.VERSION_STRING, string)
        self.assertEqual(demill.version(), string)
        self.assertEqual(demill.version_number(), demill.VERSION_NUMBER)
        demill.check_version()
        newer = demill.VERSION_NUMBER + 100
        with self.assertRaises(demill.VersionError) as cm:
            demill.check_version(newer)
        self.assertIn(str(newer), str(cm.exception))

    def test_every_error_code_has_its_exception(self):
        for code in Status:
            if code is not Status.OK:
                cls = ERRORS[code]
                self.assertTrue(issubclass(cls, Error))
                e = demill.errors.error_for(code, "text")
                self.assertIs(type(e), cls)
                self.assertEqual((e.code, e.message), (code, "text"))
        self.assertEqual(len(set(ERRORS.values())), len(Status) - 1)


class Prototypes(unittest.TestCase):
    def test_every_function_has_a_prototype_of_its_arity(self):
        funcs = header_functions()
        self.assertGreater(len(funcs), 45)
        table = {**_lib.PROTOTYPES, **_lib.OPTIONAL_PROTOTYPES}
        for name, arity in funcs.items():
            with self.subTest(function=name):
                self.assertIn(name, table)
                self.assertEqual(len(table[name][1]), arity)
                self.assertTrue(_lib.lib.has(name))

    def test_every_function_is_wrapped(self):
        """Each C function is called by the package outside the loader."""
        source = "\n".join(p.read_text() for p in (PYTHON_DIR / "demill").glob("*.py")
                           if p.name != "_lib.py")
        table = {**_lib.PROTOTYPES, **_lib.OPTIONAL_PROTOTYPES}
        for name in table:
            with self.subTest(function=name):
                self.assertRegex(source, rf"\b{name}\b", "not wrapped")

    def test_optional_functions_are_declared_when_present(self):
        for name in _lib.OPTIONAL_PROTOTYPES:
            fn = getattr(_lib.lib, name)
            if _lib.lib.has(name):
                self.assertIsNotNone(fn.argtypes)
            else:
                with self.assertRaises(demill.Unsupported):
                    fn()


if __name__ == "__main__":
    unittest.main()
