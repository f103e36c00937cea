#!/usr/bin/env python3
"""Fails when a Core header reports errors in another style than bool + std::string& error.

Core's fallible public functions return bool and fill a `std::string& error` naming the problem
and the ids involved (Docs/Decisions.md, "One error style"). This check keeps a second style
from coming back through a header:

    CoreErrorStyle.py <source folder>
    CoreErrorStyle.py --self-test

Checked: every .h below Core/, comments and string literals left out. A finding is
  - a status type: a struct or class named ...Status or ...Outcome (as TraceStatus was);
  - an exception type: a struct or class deriving from std::exception or one of its standard
    subclasses;
  - a `throw`, but `throw std::bad_alloc()` (an allocator failing as the standard ones do).
Scene/SceneError.h is Scene's own exception, included only by Scene's sources, whose public
functions catch it: it is the one header allowed an exception type.
"""
import os
import re
import sys

PRIVATE = {"Core/Scene/SceneError.h"}

STATUS_TYPE = re.compile(r"\b(?:struct|class)\s+(\w*(?:Status|Outcome))\b(?!\s*;)")
EXCEPTION_TYPE = re.compile(
    r"\b(?:struct|class)\s+(\w+)\s*(?:final\s*)?:\s*(?:public\s+)?std::"
    r"(?:exception|runtime_error|logic_error|invalid_argument|out_of_range|domain_error|"
    r"length_error|range_error|overflow_error|underflow_error|system_error)\b")
THROW = re.compile(r"\bthrow\b(?!\s+std::bad_alloc\s*\(\s*\))")
COMMENT_OR_STRING = re.compile(r"//[^\n]*|/\*.*?\*/|\"(?:\\.|[^\"\\\n])*\"|'(?:\\.|[^'\\\n])*'",
                               re.S)


def code_of(text):
    """The text with comments and literals blanked (line numbers kept)."""
    return COMMENT_OR_STRING.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def findings(text):
    """(line, what) for every finding in one header's text."""
    code = code_of(text)
    found = []
    for pattern, what in ((STATUS_TYPE, "status type"), (EXCEPTION_TYPE, "exception type"),
                          (THROW, "throw")):
        for m in pattern.finditer(code):
            found.append((code.count("\n", 0, m.start()) + 1, what + ": " + m.group(0).strip()))
    return sorted(found)


def self_test():
    assert findings("struct TraceStatus\n{\n  bool Ok;\n};") == [(1, "status type: struct TraceStatus")]
    assert findings("struct SceneError : std::runtime_error {};")[0][1].startswith("exception")
    assert findings("void f() { throw 1; }") == [(1, "throw: throw")]
    assert findings("void f() { throw std::bad_alloc(); }") == []
    assert findings("// throws when ...\nconst char* s = \"throw\";\nstruct Status;") == []
    assert findings("bool Read(std::string& error);") == []
    print("self-test passed")


def main(argv):
    if argv[1:] == ["--self-test"]:
        self_test()
        return 0
    root = argv[1]
    bad = []
    for folder, _, files in os.walk(os.path.join(root, "Core")):
        for name in sorted(files):
            if not name.endswith(".h"):
                continue
            path = os.path.join(folder, name)
            relative = os.path.relpath(path, root).replace(os.sep, "/")
            if relative in PRIVATE:
                continue
            with open(path, encoding="utf-8") as f:
                for line, what in findings(f.read()):
                    bad.append("%s:%d: %s" % (relative, line, what))
    for b in bad:
        print(b)
    if bad:
        print("%d finding(s): Core reports errors as bool + std::string& error "
              "(Docs/Decisions.md, \"One error style\")" % len(bad))
        return 1
    print("Core headers: one error style")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
