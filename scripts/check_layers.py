#!/usr/bin/env python3
"""Checks that the folders of src/ include one another in one direction only, and that no include
cycle exists between files.

    python3 scripts/check_layers.py src                 # exit 0, or one line per violation and exit 1
    python3 scripts/check_layers.py ROOT --expect FILE  # exit 0 iff the violations are exactly FILE's lines ('#' lines aside)

Every `#include "..."` of every file under ROOT is resolved as the compiler resolves it (the including
file's folder first, then ROOT, which is the project's include directory). A file may include files of
its own folder and of folders of lower rank in LAYERS, and urbis.h. Violations, each on one line:
  (a) a folder includes a folder of higher rank, or of equal rank but another folder;
  (b) files include one another in a cycle (one line per cycle found, naming every file on it);
  (c) a folder, or a file directly in ROOT, is not in LAYERS;
  (d) a quoted include resolves to no file under ROOT (it would escape the check).
Paths in the messages start at ROOT's own name (`src/scene/scene.h`), so that they read the same from
any working directory. Standard library only.
"""

import argparse
import os
import re
import sys

# The layers of src/, lowest first: a folder (or a file directly in src/) and its rank. Lower ranks
# know nothing of higher ones; folders of one rank are siblings that do not include each other.
LAYERS = {
    "urbis.h": 0,       # URBIS_HD and the exact arithmetic helpers: the only test of __CUDACC__/__CUDA_ARCH__
    "math": 0,          # vectors, frames, bounds, rng, sampling with its pdf (host+device)
    "base": 1,          # what every layer shares on the host: the error type InputError and FailureKind,
                        # name/value tables of choices, the memory a step requires, the process's own memory
    "io": 2,            # files written to a temporary and renamed; output paths checked before any work
    "astro": 2,         # civil time, the sun's and the moon's positions, sidereal time (host only)
    "film": 3,          # images, accumulation, AOVs, tone mapping, PNG and EXR files
    "accel": 4,         # BVH nodes, the build and the traversal; knows math only
    "scene": 5,         # host+device POD records (triangles, walls, ground, materials, prim kinds and refs,
                        # surface parts, camera, render settings, light records), SceneView and the host
                        # Scene with its build; never intersectors or light sampling
    "geometry": 6,      # one intersector per primitive kind, the leaf dispatch over the kinds, traceScene
    "media": 6,         # participating media: the atmosphere's tables and look-ups, aerial perspective
    "lights": 7,        # one header per light kind and the fold over them, the light sampler, MIS, scene bounds
    "integrators": 8,   # the integrator interface, the path tracer, the AOV pass
    "model": 9,         # the city model: buildings, parts, polygons and their GEOS wrapper, the reasons buildings were dropped
    "planet": 9,        # whole planets: the record around a camera (double on the host), their scene
    "osm": 10,          # OpenStreetMap import into the city model
    "layout": 10,       # procedurally generated cities as a city model
    "streets": 11,      # city model -> street meshes and records: roads, junctions, sidewalks, markings
                        # records, crossings, bridges, railways, ground cover, water, street lamps
    "terrain": 11,      # terrain parameters, DEM rasters (GDAL) and fBm sampled into the marched heightfield
    "nature": 11,       # city model -> trees: placement, records, triangle twin (a sibling of streets)
    "citygen": 12,      # city model -> meshes and scene records (buildings, roofs, facades), streets joined in
    "description": 13,  # the scene description and its JSON scene files
    "cpu": 14,          # the CPU backend (TBB)
    "gpu": 14,          # the CUDA backend; shares nothing with cpu/ but what lies below both
    "cluster": 14,      # MPI: the job's ranks, the tile queue of one frame, frames spread over ranks; a process's GPUs
    "prepare": 14,      # description -> scene: the city loaded and meshed or the planet built, the camera
                        # chosen and checked, the clouds, the lights and the atmosphere
    "export": 14,       # the triangle twin as glTF and OBJ files (tinygltf), whole or in tiles
    "animation": 14,    # camera paths and time-of-day keyframes: the scene description of any instant
    "render": 15,       # the Renderer every front-end drives: an integrator's passes and state over the devices
    "viewer": 16,       # the viewer: its session over a Renderer, camera, input, edits, scripts, panel and window
    "app": 17,          # the urbis commands
}

# The portability header sits under everything: any folder may include it, math/ of its own rank too.
INCLUDED_BY_ALL = {"urbis.h"}

SOURCE_SUFFIXES = (".h", ".hpp", ".cuh", ".inl", ".cpp", ".cc", ".cu")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def layer_of(relative_path):
    """The LAYERS key of a path relative to the root: its first folder, or the file's name if at the top."""
    return relative_path.split("/", 1)[0]


def read_sources(root):
    """Every source file under root, as root-relative paths with '/' separators, sorted."""
    found = []
    for folder, subfolders, files in os.walk(root):
        subfolders.sort()
        for name in files:
            if name.endswith(SOURCE_SUFFIXES):
                found.append(os.path.relpath(os.path.join(folder, name), root).replace(os.sep, "/"))
    return sorted(found)


def quoted_includes(path):
    """The text of each `#include "..."` line of a file, in order."""
    with open(path, encoding="utf-8", errors="replace") as source:
        return [match.group(1) for line in source if (match := INCLUDE.match(line))]


def resolve(root, including, text, known):
    """The root-relative path a quoted include names: the including file's folder first, then root."""
    beside = os.path.normpath(os.path.join(os.path.dirname(including), text)).replace(os.sep, "/")
    if beside in known:
        return beside
    from_root = os.path.normpath(text).replace(os.sep, "/")
    return from_root if from_root in known else None


def layer_violations(shown, files, edges):
    """Rules (a), (c) and (d) over the files and their include edges (file, include text, included file)."""
    problems = [f"{shown}/{layer}: not in the layer table of scripts/check_layers.py"
                for layer in sorted({layer_of(f) for f in files} - set(LAYERS))]
    for including, text, included in edges:
        if included is None:
            problems.append(f"{shown}/{including} includes {text}: no such file under {shown}/")
            continue
        source, target = layer_of(including), layer_of(included)
        if source == target or source not in LAYERS or target not in LAYERS or target in INCLUDED_BY_ALL:
            continue
        if LAYERS[target] >= LAYERS[source]:
            problems.append(f"{shown}/{including} includes {text}: "
                            f"{source} ({LAYERS[source]}) may not include {target} ({LAYERS[target]})")
    return problems


def strongly_connected(graph):
    """Tarjan's strongly connected components of {file: [included files]}, iteratively."""
    index, low, on_stack, stack, components = {}, {}, set(), [], []
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, iter(graph[start]))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is None:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[node])
                if low[node] == index[node]:
                    component = []
                    while True:
                        member = stack.pop()
                        on_stack.discard(member)
                        component.append(member)
                        if member == node:
                            break
                    components.append(sorted(component))
            elif child not in index:
                index[child] = low[child] = len(index)
                stack.append(child)
                on_stack.add(child)
                work.append((child, iter(graph[child])))
            elif child in on_stack:
                low[node] = min(low[node], index[child])
    return components


def shortest_cycle(graph, start, members):
    """The shortest include path from start back to itself inside one strongly connected component."""
    previous = {start: None}
    frontier = [start]
    while frontier:
        following = []
        for node in frontier:
            for child in graph[node]:
                if child == start:
                    path = [node]
                    while previous[path[-1]] is not None:
                        path.append(previous[path[-1]])
                    return list(reversed(path)) + [start]
                if child in members and child not in previous:
                    previous[child] = node
                    following.append(child)
        frontier = following
    return [start, start]


def cycle_violations(shown, edges):
    """Rule (b): one line per strongly connected component of the include graph that holds a cycle."""
    graph = {}
    for including, _, included in edges:
        graph.setdefault(including, [])
        if included is not None:
            graph.setdefault(included, [])
            if included not in graph[including]:
                graph[including].append(included)
    for children in graph.values():
        children.sort()
    problems = []
    for component in strongly_connected(graph):
        start = component[0]
        if len(component) > 1 or start in graph[start]:
            cycle = shortest_cycle(graph, start, set(component))
            problems.append("include cycle: " + " -> ".join(f"{shown}/{f}" for f in cycle))
    return problems


def check(root):
    """Every violation under root, sorted, and the number of files and include lines read."""
    root = os.path.normpath(root)
    shown = os.path.basename(os.path.abspath(root))
    files = read_sources(root)
    known = set(files)
    edges = [(f, text, resolve(root, f, text, known))
             for f in files for text in quoted_includes(os.path.join(root, f))]
    problems = layer_violations(shown, files, edges) + cycle_violations(shown, edges)
    return sorted(set(problems)), len(files), len(edges)


def main():
    parser = argparse.ArgumentParser(description="Fails on an include against the layers of src/ or on an include cycle.")
    parser.add_argument("root", help="the source root that includes are relative to (src)")
    parser.add_argument("--expect", metavar="FILE",
                        help="pass iff the violations are exactly FILE's lines, '#' lines aside (the check's self-test)")
    arguments = parser.parse_args()
    if not os.path.isdir(arguments.root):
        print(f"check_layers: {arguments.root}: no such folder", file=sys.stderr)
        return 2

    problems, file_count, include_count = check(arguments.root)

    if arguments.expect is not None:
        try:
            with open(arguments.expect, encoding="utf-8") as listing:
                expected = sorted({line.strip() for line in listing
                                   if line.strip() and not line.startswith("#")})
        except OSError as error:
            print(f"check_layers: {arguments.expect}: {error.strerror}", file=sys.stderr)
            return 2
        missed = [p for p in expected if p not in problems]
        extra = [p for p in problems if p not in expected]
        for line in missed:
            print(f"not reported: {line}")
        for line in extra:
            print(f"not expected: {line}")
        if missed or extra:
            return 1
        print(f"check_layers: all {len(expected)} expected violations reported, and no other")
        return 0

    for line in problems:
        print(line)
    if problems:
        print(f"check_layers: {len(problems)} violations in {file_count} files", file=sys.stderr)
        return 1
    print(f"check_layers: {file_count} files, {include_count} includes: layers in one direction, no cycle")
    return 0


if __name__ == "__main__":
    sys.exit(main())
