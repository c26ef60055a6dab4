#!/usr/bin/env python3
"""Runs the tasks of scripts/openjd/urbis_frames.yaml as an OpenJD runner would, with a stand-in for
urbis that only says which frames it was asked for, and checks that the tasks cover every frame of
FrameStart..FrameEnd exactly once (ctest: openjd_template). Needs PyYAML (python3-yaml).

    python3 scripts/openjd/check_template.py [template]
"""

import os
import re
import stat
import subprocess
import sys
import tempfile

import yaml


def expand_range(expression):
    """An OpenJD INT range expression "a-b:step" (or "a-b", "a") as a list of ints."""
    match = re.fullmatch(r"\s*(-?\d+)\s*(?:-\s*(-?\d+)\s*(?::\s*(\d+))?)?\s*", expression)
    if not match:
        raise ValueError(f"not a range expression this check knows: {expression!r}")
    first = int(match.group(1))
    last = int(match.group(2)) if match.group(2) else first
    return list(range(first, last + 1, int(match.group(3) or 1)))


def substitute(text, values):
    """Replaces every {{Name}} of `values` in `text`; fails on a name left unknown."""
    def one(match):
        name = match.group(1).strip()
        if name not in values:
            raise KeyError(f"{{{{{name}}}}} has no value")
        return str(values[name])
    return re.sub(r"\{\{([^}]*)\}\}", one, text)


def covered_frames(template, start, end, chunk, work):
    """Every frame the tasks render, in task order, running each task's script in `work`."""
    stand_in = os.path.join(work, "urbis")
    with open(stand_in, "w") as f:
        f.write('#!/bin/sh\nfor a in "$@"; do case "$prev" in --frames) echo "$a";; esac; prev=$a; done\n')
    os.chmod(stand_in, stat.S_IRWXU)
    params = {"Param.SceneFile": "scene.json", "Param.OutputDir": os.path.join(work, "out"),
              "Param.FrameStart": start, "Param.FrameEnd": end, "Param.ChunkSize": chunk,
              "Param.Urbis": stand_in, "Param.ExtraArgs": "--spp 4"}
    step = template["steps"][0]
    (task_parameter,) = step["parameterSpace"]["taskParameterDefinitions"]
    (embedded,) = step["script"]["embeddedFiles"]
    frames = []
    for value in expand_range(substitute(task_parameter["range"], params)):
        values = dict(params, **{f"Task.Param.{task_parameter['name']}": value})
        script = os.path.join(work, embedded["name"])
        with open(script, "w") as f:
            f.write(substitute(embedded["data"], values))
        os.chmod(script, stat.S_IRWXU)
        values[f"Task.File.{embedded['name']}"] = script
        command = substitute(step["script"]["actions"]["onRun"]["command"], values)
        asked = subprocess.run([command], capture_output=True, text=True, check=True).stdout.split()
        for frames_arg in asked:
            first, last = (int(x) for x in frames_arg.split(":"))
            frames.extend(range(first, last + 1))
    return frames


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "urbis_frames.yaml")
    with open(path) as f:
        template = yaml.safe_load(f)
    if template.get("specificationVersion") != "jobtemplate-2023-09":
        sys.exit(f"{path}: specificationVersion is not jobtemplate-2023-09")
    failures = 0
    for start, end, chunk in [(1, 100, 10), (1, 100, 7), (0, 0, 5), (5, 9, 1), (10, 12, 50)]:
        with tempfile.TemporaryDirectory() as work:
            frames = covered_frames(template, start, end, chunk, work)
        if frames != list(range(start, end + 1)):
            print(f"{path}: frames {start}-{end} in chunks of {chunk}: the tasks render {frames}")
            failures += 1
    if failures:
        sys.exit(1)
    print(f"check_template: {path}: every frame once, in 5 splits")


if __name__ == "__main__":
    main()
