#!/usr/bin/env python3
"""Fails unless the filter tests mirror Filters/ as the Core tests mirror Core/.

    FilterTestLayout.py <source dir>

Every filter class Filters/vtkBoolSurf<Name>.h (a header declaring its class's static New():
the base classes, the names header and the settings macros have none, and the filters' tests
exercise them) has its tests in Testing/Cxx/Filters/<Name>/ (at least one Test*.cxx), and every
folder there names a filter (or is ExampleStage/, the stage that Docs/Architecture.md walks
through). A newcomer then finds a filter's tests where its name says, and a new filter without
tests fails here.
"""
import os
import re
import sys

OTHER_FOLDERS = {"ExampleStage"}


def main(root):
    filters = set()
    for name in os.listdir(os.path.join(root, "Filters")):
        if name.startswith("vtkBoolSurf") and name.endswith(".h"):
            with open(os.path.join(root, "Filters", name), encoding="utf-8") as f:
                if not re.search(r"static\s+" + name[:-2] + r"\s*\*\s*New\(\)", f.read()):
                    continue  # not a filter: a base class, the names, the settings macros
            filters.add(name[len("vtkBoolSurf"):-2] or "BoolSurf")
    tests = os.path.join(root, "Testing", "Cxx", "Filters")
    folders = {d for d in os.listdir(tests) if os.path.isdir(os.path.join(tests, d))}
    problems = []
    for f in sorted(filters):
        folder = os.path.join(tests, f)
        if not os.path.isdir(folder):
            problems.append(f"filter vtkBoolSurf{f if f != 'BoolSurf' else ''} has no test folder "
                            f"Testing/Cxx/Filters/{f}/")
        elif not any(n.startswith("Test") and n.endswith(".cxx") for n in os.listdir(folder)):
            problems.append(f"Testing/Cxx/Filters/{f}/ holds no Test*.cxx")
    for d in sorted(folders - filters - OTHER_FOLDERS):
        problems.append(f"Testing/Cxx/Filters/{d}/ names no filter (Filters/vtkBoolSurf{d}.h)")
    loose = [n for n in os.listdir(tests) if n.endswith(".cxx")]
    for n in sorted(loose):
        problems.append(f"Testing/Cxx/Filters/{n} belongs in the folder of the filter it tests")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
