#!/usr/bin/env python3
"""Merges recorded scene results into Testing/Data/scene_expectations.json.

    BOOLSURF_RECORD_SCENES=/tmp/scenes ctest --test-dir build -R SceneRegression
    python3 Testing/Data/update_scene_expectations.py /tmp/scenes

With --init SCENES_DIR, first adds an entry (status "new") for every scene file of SCENES_DIR
(../shared/data/boolsurf-scenes) that the expectations do not list yet; rebuild and run the
suite in record mode to fill them in. Entries with status "skipped" keep their reason and are
never overwritten.
"""
import argparse
import glob
import json
import os

here = os.path.dirname(os.path.abspath(__file__))
path = os.path.join(here, "scene_expectations.json")
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("record_dir", nargs="?")
parser.add_argument("--init", metavar="SCENES_DIR")
args = parser.parse_args()

doc = json.load(open(path)) if os.path.exists(path) else {"scenes": {}}
scenes = doc.setdefault("scenes", {})
if args.init:
    for f in sorted(glob.glob(os.path.join(args.init, "**", "*.json"), recursive=True)):
        scenes.setdefault(os.path.relpath(f, args.init), {"status": "new"})
if args.record_dir:
    for f in sorted(glob.glob(os.path.join(args.record_dir, "*"))):
        for name, result in json.load(open(f)).items():
            if scenes.get(name, {}).get("status") == "skipped":
                continue
            result.pop("seconds", None)
            scenes[name] = result
doc["scenes"] = dict(sorted(scenes.items()))
with open(path, "w") as out:
    json.dump(doc, out, indent=1)
    out.write("\n")
print("%s: %d scenes" % (path, len(scenes)))
