#!/usr/bin/env python3
"""Checks that the commands README.md and docs/*.md name still exist.

Every measured number in the docs names the command that produced it; this
script checks that each such command can still be run as written:

  * a repository path a command starts with (scripts/…, verify/….py,
    papers_figures/…, tests/…, python3 <path>) exists in the checkout;
  * a program under build/release/ is a target of the build directory
    given: the program is there, or CMake made the folder of a target of that
    name (CMakeFiles/NAME.dir), as it does for programs outside `all` (the
    benchmarks, which CI's build does not compile);
  * `skelconv SUB …` names a subcommand of the built command, and every
    --option it uses appears in `skelconv SUB --help`.

Commands are read from fenced code blocks (one per line, `$ ` prompts
dropped) and from inline code spans. Placeholders in capitals or angle
brackets (SKELETON.json, <file>) are not checked; nor is anything that is
not a command (a span that does not start with one of the forms above).

    scripts/check_docs_commands.py BUILD_DIR [FILE.md ...]

Exit status 0 when every command checks, 1 with one line per problem
(file:line: what is wrong) and "CHECK-FAILED: N stale commands" otherwise.
"""
from __future__ import annotations

import re
import shlex
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# A repository path at the start of a command: these folders hold programs
# and scripts a reader runs from the checkout's root.
REPO_PREFIXES = ("scripts/", "verify/", "papers_figures/", "tests/", "bench/", "python/", "codegen/", "tools/")
BUILD_PREFIX = "build/release/"
INLINE_CODE = re.compile(r"`([^`\n]+)`")


def commands_in(path: Path):
    """(line number, command text) of every candidate command in a Markdown file."""
    in_fence = False
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
        stripped = line.strip()
        if stripped.startswith("```"):
            in_fence = not in_fence
            continue
        if in_fence or line.startswith("    "):
            yield number, stripped.removeprefix("$ ")
        else:
            for span in INLINE_CODE.findall(line):
                yield number, span.strip()


def is_placeholder(token: str) -> bool:
    return "<" in token or "*" in token or "{" in token or "..." in token or "…" in token or re.search(r"[A-Z]{3,}", token) is not None


class Checker:
    def __init__(self, build_dir: Path):
        self.build_dir = build_dir
        self.skelconv = build_dir / "src" / "skelconv"
        self.help_cache: dict[str, str | None] = {}
        self.problems: list[str] = []
        self.checked = {"skelconv": 0, "build": 0, "repository": 0}

    def help_of(self, subcommand: str) -> str | None:
        """`skelconv SUB --help`, or None when SUB is not a subcommand."""
        if subcommand not in self.help_cache:
            run = subprocess.run([str(self.skelconv), subcommand, "--help"], capture_output=True, text=True)
            self.help_cache[subcommand] = run.stdout if run.returncode == 0 else None
        return self.help_cache[subcommand]

    def check(self, where: str, text: str) -> None:
        try:
            tokens = shlex.split(text, comments=False)
        except ValueError:
            return  # not a shell command (an unbalanced quote in prose)
        # Leading VAR=value assignments and `python3`/`bash` launchers.
        while tokens and re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*=\S*", tokens[0]):
            tokens.pop(0)
        if tokens and tokens[0] in ("python3", "bash", "time"):
            tokens.pop(0)
        if not tokens:
            return
        program = tokens[0].removeprefix("./")
        if program == "skelconv" or program == BUILD_PREFIX + "src/skelconv":
            self.check_skelconv(where, tokens[1:])
        elif program.startswith(BUILD_PREFIX):
            self.checked["build"] += 1
            if not is_placeholder(program) and not self.is_target(program.removeprefix(BUILD_PREFIX)):
                self.problems.append(f"{where}: {program} is not a program of the build (no such program or target in {self.build_dir})")
        elif program.startswith(REPO_PREFIXES):
            self.checked["repository"] += 1
            if not is_placeholder(program) and not (ROOT / program).exists():
                self.problems.append(f"{where}: {program} does not exist in the repository")

    def is_target(self, relative: str) -> bool:
        path = self.build_dir / relative
        return path.exists() or (path.parent / "CMakeFiles" / (path.name + ".dir")).is_dir()

    def check_skelconv(self, where: str, arguments: list[str]) -> None:
        if not arguments or arguments[0].startswith("-") or is_placeholder(arguments[0]):
            return
        subcommand = arguments[0]
        if not re.fullmatch(r"[a-z][a-z-]*", subcommand):
            return  # prose such as "skelconv's"
        self.checked["skelconv"] += 1
        text = self.help_of(subcommand)
        if text is None:
            self.problems.append(f"{where}: `skelconv {subcommand}` is not a subcommand of {self.skelconv}")
            return
        for argument in arguments[1:]:
            option = argument.split("=", 1)[0]
            if option.startswith("--") and len(option) > 2 and not is_placeholder(option):
                if not re.search(re.escape(option) + r"\b", text):
                    self.problems.append(f"{where}: `skelconv {subcommand}` has no option {option}")


def main(argv: list[str]) -> int:
    if len(argv) < 2:
        print(__doc__.strip().splitlines()[-5], file=sys.stderr)
        return 2
    build_dir = Path(argv[1]).resolve()
    if not (build_dir / "src" / "skelconv").exists():
        print(f"check_docs_commands: {build_dir}/src/skelconv is missing: build the command first", file=sys.stderr)
        return 2
    files = [Path(f) for f in argv[2:]] or [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
    checker = Checker(build_dir)
    count = 0
    for path in files:
        for number, text in commands_in(path):
            count += 1
            shown = path.relative_to(ROOT) if path.is_relative_to(ROOT) else path
            checker.check(f"{shown}:{number}", text)
    for problem in checker.problems:
        print(problem)
    kinds = ", ".join(f"{n} {kind}" for kind, n in checker.checked.items())
    print(f"check_docs_commands: {len(files)} files, {count} code lines and spans, commands checked: {kinds}; "
          f"{len(checker.problems)} problems")
    if checker.problems:
        print(f"CHECK-FAILED: {len(checker.problems)} stale commands")
    return 1 if checker.problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
