#!/usr/bin/env python3
"""Fails when Core's folders include each other in a cycle.

    CoreLayers.py <source dir>

Core is one folder per stage of the method; a folder may include the folders below it
(Mesh at the bottom), never one that includes it back: a cycle means two stages can no longer
be understood, tested or changed apart. Prints the folders' include graph on failure.
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([A-Za-z]+)/[^"]+"', re.M)


def graph(core):
    edges = {}
    for folder in sorted(os.listdir(core)):
        path = os.path.join(core, folder)
        if not os.path.isdir(path):
            continue
        targets = set()
        for dirpath, _, files in os.walk(path):
            for name in files:
                if name.endswith((".h", ".cxx")):
                    with open(os.path.join(dirpath, name), encoding="utf-8") as f:
                        targets.update(INCLUDE.findall(f.read()))
        edges[folder] = sorted(t for t in targets if t != folder and t in os.listdir(core))
    return edges


def find_cycle(edges):
    state = {}
    stack = []

    def visit(node):
        state[node] = 1
        stack.append(node)
        for nxt in edges.get(node, []):
            if state.get(nxt) == 1:
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state:
                cycle = visit(nxt)
                if cycle:
                    return cycle
        stack.pop()
        state[node] = 2
        return None

    for node in edges:
        if node not in state:
            cycle = visit(node)
            if cycle:
                return cycle
    return None


def main(root):
    edges = graph(os.path.join(root, "Core"))
    cycle = find_cycle(edges)
    if cycle:
        print("Core folders include each other in a cycle: " + " -> ".join(cycle))
        for folder, targets in edges.items():
            print(f"  {folder} -> {' '.join(targets)}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
