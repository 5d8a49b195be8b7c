#!/usr/bin/env python3
"""A test of the tests: every can-fail twin goes red when its check is
replaced by a stub that accepts everything.

    check_can_fail_twins.py BUILD_DIR TWIN...

A twin (a ctest such as glsl_numeric_can_fail) runs a check on a
purpose-built fault through verify/expect_run.sh (or expect_compare.sh),
which passes only on the check's exit status 1 and its CHECK-FAILED line.
A twin earns its place only if it would fail were the check broken. For each
TWIN this script takes the twin's command, working directory and
environment from ctest (`ctest --show-only=json-v1`), replaces the check by
a stub that accepts everything (STUBS below: the check's own function
answering "all good", or a stand-in program that exits 0 on anything), runs
the command, and requires:
  - the twin fails (a non-zero exit status), and
  - it fails because the stubbed check accepted the fault: the wrapper's line
    "... exited with status 0, expected 1" (a stub that crashed, or a twin
    that fails for another reason, proves nothing and is reported).
The stubs are made in a scratch folder; nothing in the source tree changes.
Exit status 0 when every twin went red as required, 1 otherwise.
Python 3 standard library only.
"""
import json
import os
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent

# What a stubbed twin must print: its wrapper saw the check accept the fault
# (expect_run.sh: "'X' exited with status 0, expected 1"; expect_compare.sh:
# "compare exited with 0, expected 1").
ACCEPTED = re.compile(r"exited with (status )?0, expected 1")


def function_returns(name, value):
    """A rewrite of a Python script: function (or method) NAME returns VALUE
    at once, whatever its input."""
    def rewrite(text):
        lines = text.splitlines(keepends=True)
        for k, line in enumerate(lines):
            found = re.match(r"(\s*)def " + name + r"\(", line)
            if found:
                end = k
                while not lines[end].rstrip().endswith(":"):
                    end += 1
                lines.insert(end + 1, found.group(1) + "    return " + value + "  # stub: accepts everything\n")
                return "".join(lines)
        sys.exit(f"check_can_fail_twins: no function {name} to stub")
    return rewrite


def replaced(pattern, replacement):
    """A rewrite of a script's text: every match of PATTERN replaced."""
    def rewrite(text):
        out, count = re.subn(pattern, replacement, text)
        if not count:
            sys.exit(f"check_can_fail_twins: nothing matches {pattern!r} to stub")
        return out
    return rewrite


# How each twin's check is stubbed:
#   ("path", PROGRAM)           a PROGRAM on PATH that exits 0 on anything;
#   ("program", NAME, N)        the N-th argument (0: first) whose file name is
#                               NAME replaced by a program that exits 0;
#   ("script", PATH, REWRITE)   the repository script PATH replaced by a copy
#                               rewritten by REWRITE (in a mirror of the
#                               source tree, so that the files it finds next
#                               to itself are still there).
STUBS = {
    "glsl_compile_check_can_fail": ("path", "glslangValidator"),
    "view_pages_check_can_fail": ("path", "glslangValidator"),
    "glsl_numeric_can_fail": ("script", "tests/glsl/check_glsl_numeric.py", function_returns("relative_error", "0.0")),
    "glsl_numeric_chromium_can_fail": ("script", "tests/glsl/check_glsl_numeric.py",
                                       function_returns("relative_error", "0.0")),
    "view_browser_check_can_fail": ("script", "tests/view/check_view_browser.py",
                                    function_returns("silhouette_iou", "1.0")),
    "docs_commands_check_can_fail": ("script", "scripts/check_docs_commands.py", function_returns("check", "None")),
    "cli_checker_refuses_truncated_output": ("script", "tests/cli/run_cli_case.cmake",
                                             replaced(r"message\(FATAL_ERROR", "message(STATUS")),
    # expect_run.sh checked by itself: the inner one (the second) is the check.
    "expect_run_refuses_a_crash_after_the_line": ("program", "expect_run.sh", 1),
    "expect_run_refuses_a_wrong_status": ("program", "expect_run.sh", 1),
    "expect_run_refuses_a_missing_line": ("program", "expect_run.sh", 1),
    "verify_compare_polygon_catches_worsened": ("script", "verify/compare_polygon_report.py",
                                                function_returns("failures", "[]")),
    "verify_sweep_fails_on_exclusion_storm": ("program", "skelconv-verify", 0),
    "verify_sweep_fails_on_wrong_kernel": ("program", "skelconv-verify", 0),
    "verify_polygon_sweep_fails_on_exclusion_storm": ("program", "skelconv-verify-polygons", 0),
    "verify_compare_catches_perturbation": ("program", "skelconv-verify", 0),
}


def ctest_entries(build):
    """Every test of BUILD: name -> (command, properties)."""
    listing = subprocess.run(["ctest", "--test-dir", str(build), "--show-only=json-v1"],
                             capture_output=True, text=True, check=True)
    return {test["name"]: (test.get("command", []), {p["name"]: p["value"] for p in test.get("properties", [])})
            for test in json.loads(listing.stdout)["tests"]}


def accept_all(folder, name):
    """A program NAME in FOLDER that ignores its input and exits 0."""
    folder.mkdir(parents=True, exist_ok=True)
    program = folder / name
    program.write_text("#!/bin/sh\n# a stub check: accepts everything\nexit 0\n")
    program.chmod(0o755)
    return program


def mirror(scratch, relative, rewrite):
    """A mirror of the source tree in SCRATCH (symbolic links) in which the
    file RELATIVE is a rewritten copy: the stubbed script finds what lies next
    to it. Returns the copy's path."""
    parts = pathlib.PurePosixPath(relative).parts
    here, source = scratch / "source", ROOT
    here.mkdir()
    for part in parts:
        for entry in source.iterdir():
            if entry.name != part:
                (here / entry.name).symlink_to(entry)
        source, here = source / part, here / part
        if source.is_dir():
            here.mkdir()
    here.write_text(rewrite(source.read_text()))
    here.chmod(source.stat().st_mode)
    return here


def stubbed_command(name, command, scratch, env):
    kind = STUBS[name][0]
    if kind == "path":
        stubs = scratch / "bin"
        accept_all(stubs, STUBS[name][1])
        env["PATH"] = f"{stubs}{os.pathsep}{env.get('PATH', '')}"
        return command
    if kind == "program":
        _, program, which = STUBS[name]
        hits = [k for k, arg in enumerate(command) if pathlib.Path(arg).name == program]
        if len(hits) <= which:
            sys.exit(f"check_can_fail_twins: {name}: no argument {program} to stub")
        stub = accept_all(scratch / "bin", program)
        command = list(command)
        command[hits[which]] = str(stub)
        return command
    _, relative, rewrite = STUBS[name]
    original = str(ROOT / relative)
    if original not in command:
        sys.exit(f"check_can_fail_twins: {name} does not run {relative}")
    copy = str(mirror(scratch, relative, rewrite))
    return [copy if arg == original else arg for arg in command]


def run_stubbed(name, command, properties):
    env = dict(os.environ)
    for setting in properties.get("ENVIRONMENT", []):
        key, _, value = setting.partition("=")
        env[key] = value
    with tempfile.TemporaryDirectory() as scratch:
        command = stubbed_command(name, command, pathlib.Path(scratch), env)
        run = subprocess.run(command, cwd=properties.get("WORKING_DIRECTORY"), env=env,
                             capture_output=True, text=True, timeout=1800)
    output = run.stdout + run.stderr
    if run.returncode == 0:
        return f"{name}: stays green with its check stubbed (exit status 0):\n{output[-1500:]}"
    if not ACCEPTED.search(output):
        return (f"{name}: failed (status {run.returncode}) but not because the stubbed check accepted the fault:"
                f"\n{output[-1500:]}")
    line = next(l for l in output.splitlines() if ACCEPTED.search(l))
    print(f"check_can_fail_twins: {name}: red with its check stubbed ({STUBS[name][0]} stub): {line.strip()}",
          flush=True)
    return None


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    build, names = pathlib.Path(sys.argv[1]), sys.argv[2:]
    unknown = [n for n in names if n not in STUBS]
    if unknown:
        sys.exit(f"check_can_fail_twins: no stub for {', '.join(unknown)} (STUBS)")
    tests = ctest_entries(build)
    missing = [n for n in names if n not in tests]
    if missing:
        sys.exit(f"check_can_fail_twins: not tests of {build}: {', '.join(missing)}")
    problems = [p for p in (run_stubbed(name, *tests[name]) for name in names) if p]
    for problem in problems:
        print("check_can_fail_twins: FAIL " + problem, file=sys.stderr)
    print(f"check_can_fail_twins: {len(names) - len(problems)} of {len(names)} twins red with their check stubbed")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
