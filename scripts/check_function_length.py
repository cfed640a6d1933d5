#!/usr/bin/env python3
"""Lists every C++ function longer than 80 lines (issue 21, STYLE.md).

  scripts/check_function_length.py [--max N] [--report-only] [DIR ...]

Scans mlndt/, lab/, tools/ and python/src (or the folders given) for .h/.cc
files, test files (*_test.cc) excluded. A brace-matching scan: comments,
string and character literals and preprocessor lines are blanked first;
then a `{` at namespace or class scope whose head ends in `)` (optionally
followed by const/override/noexcept/-> type, or a constructor's initialiser
list) opens a function, and everything up to its matching `}` - lambdas
included - is that function. A function's length counts the lines from its
opening brace to its closing one. Prints `path:line: Name N lines` for each
one over the limit and exits 1 when there is any (0 with --report-only).
"""

import argparse
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_DIRS = ["mlndt", "lab", "tools", "python/src", "integrations"]
CONTAINER = re.compile(r"\b(namespace|class|struct|union|enum)\b|extern\s*\"C\"")
# A function head: `...)` then qualifiers or a trailing return type.
FUNCTION_HEAD = re.compile(
    r"\)\s*(?:const|override|final|noexcept(?:\([^()]*\))?|mutable|&&?|->\s*[\w:<>,\s*&]+|\s)*$"
)
CONTROL = re.compile(r"^\s*(if|for|while|switch|catch|do|else)\b")
# The function's name: the identifier before the parameter list's `(`.
NAME = re.compile(r"([~\w:]+(?:<[^<>()]*>)?)\s*\(")


def blank(text):
    """Text with comments, literals and preprocessor lines replaced by spaces
    (newlines kept, so line numbers stay)."""
    out = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c == "#":
            # A preprocessor line, with its backslash continuations.
            while i < n and not (text[i] == "\n" and text[i - 1] != "\\"):
                out.append("\n" if text[i] == "\n" else " ")
                i += 1
            continue
        if c == "/" and text.startswith("//", i):
            while i < n and text[i] != "\n":
                out.append(" ")
                i += 1
            continue
        if c == "/" and text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
            continue
        raw = re.match(r'R"([^(\s]*)\(', text[i:i + 20]) if c == "R" else None
        if raw and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            end = text.find(")" + raw.group(1) + '"', i)
            end = n if end < 0 else end + len(raw.group(1)) + 2
            out.append('"' + re.sub(r"[^\n]", " ", text[i + 1:end - 1]) + '"')
            i = end
            continue
        if c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():
                out.append(" ")  # a digit separator, 1'000
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (j - i - 1) + c)
            i = j + 1
            continue
        out.append(c)
        line_start = c == "\n" or (line_start and c in " \t")
        i += 1
    return "".join(out)


def functions(text):
    """Yields (name, first line, number of lines) for every function body."""
    code = blank(text)
    stack = []  # one entry a open brace: "container", "other" or "function"
    head_start = 0
    function_open = None  # (name, line) of the function being read
    line = 1
    for i, c in enumerate(code):
        if c == "\n":
            line += 1
        elif c == "{":
            if function_open or (stack and stack[-1] == "function"):
                stack.append("inner")
                continue
            head = code[head_start:i]
            flat = " ".join(head.split())
            if FUNCTION_HEAD.search(flat) and not CONTROL.match(flat) and "(" in flat:
                names = NAME.findall(flat)
                stack.append("function")
                function_open = (names[0] if names else "?", line)
            elif CONTAINER.search(flat) and "=" not in flat:
                stack.append("container")
                head_start = i + 1
            else:
                stack.append("other")  # an initialiser: the head goes on
        elif c == "}":
            kind = stack.pop() if stack else "container"
            if kind == "function":
                name, first = function_open
                yield name, first, line - first + 1
                function_open = None
                head_start = i + 1
            elif kind == "container":
                head_start = i + 1
        elif c == ";" and (not stack or stack[-1] == "container"):
            head_start = i + 1


def source_files(dirs):
    for directory in dirs:
        for base, _, names in os.walk(os.path.join(ROOT, directory)):
            for name in sorted(names):
                if name.endswith((".h", ".cc")) and not name.endswith("_test.cc"):
                    yield os.path.join(base, name)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dirs", nargs="*", default=DEFAULT_DIRS)
    parser.add_argument("--max", type=int, default=80, help="the longest a function may be [lines]")
    parser.add_argument("--report-only", action="store_true", help="list, but exit 0")
    args = parser.parse_args()
    found = []
    for path in sorted(source_files(args.dirs)):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for name, first, length in functions(text):
            if length > args.max:
                found.append((os.path.relpath(path, ROOT), first, name, length))
    for path, first, name, length in found:
        print("%s:%d: %s %d lines" % (path, first, name, length))
    if found:
        print("check_function_length: %d functions over %d lines" % (len(found), args.max))
        return 0 if args.report_only else 1
    print("check_function_length: no function over %d lines in %s: ok" % (args.max, ", ".join(args.dirs)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
