#!/usr/bin/env python3
"""The include graph of wetbed's folders: how many #include <wetbed/B/...> lines each
folder A of source/ and include/wetbed/ has (A -> B), and every include that points up
the layer order core < closures < mesh < boundary_conditions < assembly < solvers <
postprocess < command_line, with the files that make it. Exit status 0; a text report on stdout.

usage: python3 scripts/include_graph.py [--dot FILE]   (FILE: Graphviz, one edge a line)"""
import argparse
import collections
import os
import re

LAYERS = ["core", "closures", "mesh", "boundary_conditions", "assembly", "solvers", "postprocess",
          "command_line"]
root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
parser = argparse.ArgumentParser()
parser.add_argument("--dot", help="also write the folder graph in Graphviz form")
args = parser.parse_args()

edges, upward = collections.Counter(), collections.defaultdict(list)
for base in ("source", os.path.join("include", "wetbed")):
    for folder, _, files in os.walk(os.path.join(root, base)):
        for name in sorted(files):
            if not name.endswith((".cc", ".h")):
                continue
            path = os.path.join(folder, name)
            relative = os.path.relpath(path, os.path.join(root, base))
            source = relative.split(os.sep)[0] if os.sep in relative else "(main)"
            for target in re.findall(r"#include <wetbed/([a-z_]+)/", open(path).read()):
                if target == source:
                    continue
                edges[(source, target)] += 1
                if source in LAYERS and target in LAYERS and LAYERS.index(target) > LAYERS.index(source):
                    upward[(source, target)].append(os.path.relpath(path, root))

print("includes between folders (A -> B: lines in A's files that include a header of B)")
for (a, b), n in sorted(edges.items()):
    print(f"  {a:20s} -> {b:20s} {n:3d}{'  (up)' if (a, b) in upward else ''}")
print(f"\nupward includes (layer order {' < '.join(LAYERS)}): {sum(len(v) for v in upward.values())}")
for (a, b), files in sorted(upward.items()):
    print(f"  {a} -> {b}: " + ", ".join(sorted(set(files))))
if args.dot:
    with open(args.dot, "w") as f:
        f.write("digraph includes {\n")
        for (a, b), n in sorted(edges.items()):
            style = ' color="red"' if (a, b) in upward else ""
            f.write(f'  "{a}" -> "{b}" [label="{n}"{style}];\n')
        f.write("}\n")
