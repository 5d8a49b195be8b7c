#!/usr/bin/env python3
"""Check the include graph of include/, src/ and generated/ (Python 3, stdlib).

Usage: scripts/check_include_graph.py [PROJECT_ROOT]

Fails (exit 1, one line per problem) when
  - an #include of a project header does not resolve to a file;
  - the graph has a cycle;
  - a header under include/ includes a header under src/ (the public API must
    compile from an installed tree, where src/ does not exist);
  - a file of src/A/ includes a private header of another folder src/B/
    (shared private headers live in src/detail/, which every folder may use);
  - an installed header (include/skelconv/ outside detail/ and the folders
    cmake/install.cmake excludes with `PATTERN name EXCLUDE`, the detail/
    headers listed in cmake/install.cmake's SKELCONV_INSTALLED_DETAIL_HEADERS,
    generated/*.hpp) includes a detail/ header that is not installed, or a
    header of an excluded folder, or the list names a detail/ header that no
    installed header includes.
System headers and third-party libraries are not followed: only includes that
start with "skelconv/", "generated/", "src/", "tools/" or are relative to the
including file are project includes.
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^">]+)[">]', re.M)
PROJECT_PREFIXES = ("skelconv/", "generated/", "src/", "tools/")


def resolve(root, including, bracket, name):
    """The project file `name` names, or None for a system/third-party one."""
    if name.startswith("skelconv/"):
        return root / "include" / name
    if name.startswith(("generated/", "src/", "tools/")):
        return root / name
    if bracket == '"':  # relative to the including file
        return (including.parent / name).resolve()
    return None


def graph(root):
    files = [p for d in ("include", "src", "generated")
             for p in sorted((root / d).rglob("*")) if p.suffix in (".hpp", ".cpp")]
    edges, problems = {}, []
    for f in files:
        rel = f.relative_to(root)
        edges[rel] = []
        for bracket, name in INCLUDE.findall(f.read_text(encoding="utf-8")):
            target = resolve(root, f, bracket, name)
            if target is None:
                continue
            if not target.is_file():
                if name.startswith(PROJECT_PREFIXES) or bracket == '"' and "/" in name:
                    problems.append(f"{rel}: #include {name} does not resolve")
                continue  # a system header included with "" (e.g. "omp.h")
            edges[rel].append(target.resolve().relative_to(root.resolve()))
    return edges, problems


def cycles(edges):
    """Each cycle once, as a list of files (iterative DFS, colours)."""
    colour, found = {}, []
    for start in edges:
        if colour.get(start):
            continue
        stack = [(start, iter(edges.get(start, [])))]
        path = [start]
        colour[start] = 1
        while stack:
            node, it = stack[-1]
            nxt = next(it, None)
            if nxt is None:
                colour[node] = 2
                stack.pop()
                path.pop()
            elif colour.get(nxt) == 1:
                found.append(path[path.index(nxt):] + [nxt])
            elif not colour.get(nxt):
                colour[nxt] = 1
                stack.append((nxt, iter(edges.get(nxt, []))))
                path.append(nxt)
    return found


def installed_detail(root):
    text = (root / "cmake" / "install.cmake").read_text(encoding="utf-8")
    m = re.search(r"set\(SKELCONV_INSTALLED_DETAIL_HEADERS\s+([^)]*)\)", text)
    if not m:
        return None
    return {pathlib.Path("include/skelconv/detail") / n for n in m.group(1).split()}


def excluded_folders(root):
    """The folders of include/skelconv/ that cmake/install.cmake does not install."""
    text = (root / "cmake" / "install.cmake").read_text(encoding="utf-8")
    return set(re.findall(r"PATTERN\s+(\w+)\s+EXCLUDE", text))


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else
                        pathlib.Path(__file__).resolve().parent.parent)
    edges, problems = graph(root)
    for c in cycles(edges):
        problems.append("include cycle: " + " -> ".join(map(str, c)))
    for f, targets in edges.items():
        parts = f.parts
        for t in targets:
            if parts[0] == "include" and t.parts[0] == "src":
                problems.append(f"{f}: a header under include/ includes {t}")
            if (parts[0] == "src" and t.parts[0] == "src" and len(parts) > 2
                    and len(t.parts) > 2 and t.parts[1] != parts[1] and t.parts[1] != "detail"):
                problems.append(f"{f}: includes {t}, private to src/{t.parts[1]}/ "
                                "(shared private headers go in src/detail/)")
    detail_list = installed_detail(root)
    if detail_list is None:
        problems.append("cmake/install.cmake: no SKELCONV_INSTALLED_DETAIL_HEADERS list")
    else:
        excluded = excluded_folders(root)
        installed = {f for f in edges if f.parts[0] == "generated" or
                     (f.parts[:2] == ("include", "skelconv") and not excluded.intersection(f.parts[2:-1]))}
        installed = {f for f in installed if f.suffix == ".hpp"}
        for f in sorted(installed):
            for t in edges[f]:
                if t.parts[:2] == ("include", "skelconv") and excluded.intersection(t.parts[2:-1]) \
                        and "detail" not in t.parts:
                    problems.append(f"{f} (installed) includes {t}, which cmake/install.cmake does not install")
        reached = set()
        for f in installed | detail_list:
            for t in edges.get(f, []):
                if "detail" in t.parts and t.parts[0] == "include":
                    reached.add(t)
                    if t not in detail_list:
                        problems.append(f"{f} (installed) includes {t}, which "
                                        "cmake/install.cmake does not install")
        for d in sorted(detail_list - reached):
            problems.append(f"cmake/install.cmake installs {d}, which no installed header includes")
        for d in sorted(detail_list):
            if d not in edges:
                problems.append(f"cmake/install.cmake lists {d}, which does not exist")
    for p in problems:
        print(p)
    print(f"include graph: {len(edges)} files, "
          f"{sum(map(len, edges.values()))} project includes, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
