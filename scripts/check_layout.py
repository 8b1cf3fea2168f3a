#!/usr/bin/env python3
"""The shape of the source tree, checked (issue 18), so that it stays the way a newcomer finds it:

- the core (src/core, include/dressed_human/core) lives in folders by layer, and a file includes
  only its own layer or the layers below it (LAYERS, lowest first);
- the core includes nothing of ROS, rviz or Ogre;
- no file in src/ or include/ is over MAX_FILE_LINES lines, no function in the core over
  MAX_FUNCTION_LINES;
- the README's layout section names every core folder;
- no Qt connection by SIGNAL()/SLOT() strings, which fail only at run time (issue 38);
- no test builds a temporary file's path from TempDir() itself: ctest runs tests in parallel
  processes, and a fixed name under TempDir() is shared between them (test/core/temp_file_path.h).

Prints each violation with its file and line and exits 1 if there is any.
Usage: scripts/check_layout.py [repository root]
"""
import os
import re
import sys

LAYERS = ["io", "skeleton", "motion", "locomotion", "surfaces", "garments", "relief", "model", "render"]
MAX_FILE_LINES = 600
MAX_FUNCTION_LINES = 120
CORE_INCLUDE = re.compile(r'^\s*#\s*include\s*"dressed_human/core/([^/"]+)/[^"]+"')
QT_STRING_CONNECTION = re.compile(r'\b(SIGNAL|SLOT)\s*\(')
SHARED_TEMP_PATH = re.compile(r'TempDir\(\)\s*\+')
TEMP_PATH_HELPER = os.path.join("test", "core", "temp_file_path.h")
FORBIDDEN_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"](ros/|rviz/|tf2_ros/|Ogre|OGRE|OgreMain)')


def source_files(root, folder):
    for directory, _, names in os.walk(os.path.join(root, folder)):
        for name in sorted(names):
            if name.endswith((".h", ".hpp", ".cpp", ".cc")):
                yield os.path.join(directory, name)


def layer_of(path, core_root):
    relative = os.path.relpath(path, core_root)
    return relative.split(os.sep)[0] if os.sep in relative else None


def strip_code_line(line):
    line = re.sub(r'"(\\.|[^"\\])*"', '""', line)
    line = re.sub(r"'(\\.|[^'\\])*'", "''", line)
    return re.sub(r"//.*", "", line)


def long_functions(lines):
    """(first line, length) of each brace block opened at namespace or class level that is not a
    namespace, class, struct, enum or initializer: a function body."""
    found = []
    stack = []  # per open brace: its kind and line
    for number, raw in enumerate(lines, 1):
        line = strip_code_line(raw)
        for position, char in enumerate(line):
            if char == "{":
                before = line[:position]
                if re.search(r"\bnamespace\b", before) or (not before.strip() and number > 1 and
                                                             re.search(r"\bnamespace\b", strip_code_line(lines[number - 2]))):
                    kind = "scope"
                elif re.search(r"^\s*(template\s*<.*>\s*)?(class|struct|union|enum)\b", before) and "(" not in before:
                    kind = "scope"
                elif all(k == "scope" for k, _ in stack) and not re.search(r"=\s*$", before):
                    kind = "function"
                else:
                    kind = "block"
                stack.append((kind, number))
            elif char == "}" and stack:
                kind, start = stack.pop()
                if kind == "function" and number - start + 1 > MAX_FUNCTION_LINES:
                    found.append((start, number - start + 1))
    return found


def matching_lines(root, folder, pattern):
    for path in source_files(root, folder):
        with open(path, encoding="utf-8") as source:
            for number, line in enumerate(source, 1):
                if pattern.search(strip_code_line(line)):
                    yield os.path.relpath(path, root), number, line.strip()


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    problems = []
    core_roots = [os.path.join(root, "src", "core"), os.path.join(root, "include", "dressed_human", "core")]
    for core_root in core_roots:
        for path in source_files(root, os.path.relpath(core_root, root)):
            shown = os.path.relpath(path, root)
            layer = layer_of(path, core_root)
            if layer not in LAYERS:
                problems.append(f"{shown}: not in a layer folder ({', '.join(LAYERS)})")
                continue
            with open(path, encoding="utf-8") as source:
                lines = source.read().split("\n")
            for number, line in enumerate(lines, 1):
                included = CORE_INCLUDE.match(line)
                if included and included.group(1) not in LAYERS:
                    problems.append(f"{shown}:{number}: includes an unknown layer '{included.group(1)}'")
                elif included and LAYERS.index(included.group(1)) > LAYERS.index(layer):
                    problems.append(f"{shown}:{number}: layer '{layer}' includes the higher layer "
                                    f"'{included.group(1)}' (includes go down: {' < '.join(LAYERS)})")
                if FORBIDDEN_INCLUDE.match(line):
                    problems.append(f"{shown}:{number}: the core includes ROS, rviz or Ogre: {line.strip()}")
            if path.endswith(".cpp"):
                for start, length in long_functions(lines):
                    problems.append(f"{shown}:{start}: a function of {length} lines (at most {MAX_FUNCTION_LINES} in the core)")
    for folder in ("src", "include"):
        for path in source_files(root, folder):
            with open(path, encoding="utf-8") as source:
                count = sum(1 for _ in source)
            if count > MAX_FILE_LINES:
                problems.append(f"{os.path.relpath(path, root)}: {count} lines (at most {MAX_FILE_LINES})")
    for folder in ("src", "include"):
        for path, number, line in matching_lines(root, folder, QT_STRING_CONNECTION):
            problems.append(f"{path}:{number}: a Qt connection by string; connect member-function pointers: {line}")
    for path, number, line in matching_lines(root, "test", SHARED_TEMP_PATH):
        if path != TEMP_PATH_HELPER:
            problems.append(f"{path}:{number}: a temporary path shared by parallel tests; use tempFilePath(): {line}")
    with open(os.path.join(root, "README.md"), encoding="utf-8") as readme:
        text = readme.read()
    layout = text[text.find("## Layout"):]
    for layer in LAYERS:
        if f"core/{layer}/" not in layout:
            problems.append(f"README.md: the layout section does not say what src/core/{layer}/ holds")
    for problem in problems:
        print(problem)
    print(f"{len(problems)} problem(s) in the source tree's layout" if problems else "layout: all checks pass")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
