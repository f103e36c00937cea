#!/usr/bin/env python3
"""Fails when an array name is spelled as a string literal outside the names header.

Every array and field-data name the filters (and the curve editor) write or read is spelled
once, in Filters/vtkBoolSurfArrayNames.h (boolsurf::names): users' scripts and files find the
data by these names (README, "Data contract"), so a second spelling is a second place to
change, and a typo there is a silent miss (GetArray returns null).

    ArrayNameLiterals.py <source folder>

Checked: every .h and .cxx file below Filters/ and Plugin/ but the names header. A finding is a
string literal given as the array-name argument of
  - VTK's name APIs: SetName, GetArray, GetAbstractArray, HasArray, RemoveArray, SetActiveScalars,
    SetActiveVectors, SetActiveNormals, SetActiveTCoords, SetActiveAttribute (first argument),
    and vtkGlyph3DMapper's SetScaleArray, SetOrientationArray, SetMaskArray;
  - the module's helpers that make or read a named array: IntArray, NamedIntArray, Ints,
    PerShapeArray (first argument), ReadInts, ReadLoops, WriteLoops, AddString, FieldString,
    WriteControlSubCurves (second argument), and any call of a
    template on a VTK array type, `Name<vtkIntArray>("...")` (first argument).
Names of proxy properties, component names and messages are not array names and not checked.
"""
import os
import re
import sys

FIRST_ARGUMENT = re.compile(
    r"\b(SetName|GetArray|GetAbstractArray|HasArray|RemoveArray|SetActiveScalars|"
    r"SetActiveVectors|SetActiveNormals|SetActiveTCoords|SetActiveAttribute|SetScaleArray|"
    r"SetOrientationArray|SetMaskArray|IntArray|NamedIntArray|Ints|PerShapeArray)\(\s*\"([^\"]*)\"")
SECOND_ARGUMENT = re.compile(r"\b(ReadInts|ReadLoops|WriteLoops|AddString|FieldString|WriteControlSubCurves)\("
                             r"\s*(?:[^,()\"]|\([^()]*\))+,\s*\"([^\"]*)\"")
ARRAY_TEMPLATE = re.compile(r"\b(\w+<\s*vtk\w*Array\s*>)\(\s*\"([^\"]*)\"")
NAMES_HEADER = "Filters/vtkBoolSurfArrayNames.h"

# Files allowed to keep literal names for a while (reported, not failed): none. A file goes
# here only while a rework elsewhere would conflict, and leaves as soon as it lands.
PENDING = set()


def findings(root, path):
    with open(os.path.join(root, path), encoding="utf-8") as f:
        text = f.read()
    for pattern in (FIRST_ARGUMENT, SECOND_ARGUMENT, ARRAY_TEMPLATE):
        for match in pattern.finditer(text):
            line = text.count("\n", 0, match.start()) + 1
            yield line, match.group(1), match.group(2)


def main(argv):
    root = argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    bad, pending = [], []
    for folder in ("Filters", "Plugin"):
        for directory, _, files in os.walk(os.path.join(root, folder)):
            for name in sorted(files):
                if not name.endswith((".h", ".cxx")):
                    continue
                path = os.path.relpath(os.path.join(directory, name), root).replace(os.sep, "/")
                if path == NAMES_HEADER:
                    continue
                for line, call, literal in findings(root, path):
                    entry = '%s:%d: %s("%s")' % (path, line, call, literal)
                    (pending if path in PENDING else bad).append(entry)
    for entry in pending:
        print("pending (listed in PENDING): " + entry)
    for entry in bad:
        print("array name spelled outside %s: %s" % (NAMES_HEADER, entry))
    if bad:
        print("%d literal array name(s): use the constants of boolsurf::names" % len(bad))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
