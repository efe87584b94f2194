#!/usr/bin/env python3
"""Lists the C++ functions longer than a limit (lines from the signature to the closing brace).

A brace counter, not a parser: comments, strings and character literals are blanked first;
a block opened at namespace or class scope whose head ends in ')' (or ') const', 'override',
an initialiser list, a trailing return type) is a function, and a block inside a function
(a lambda, a loop) counts towards it. Good enough for this code base's style (clang-format).
"""
import argparse
import os
import re
import sys

HEAD_NOT_FUNCTION = re.compile(r"\b(namespace|class|struct|enum|union)\b|=\s*$|^\s*extern\s")


def blank(text):
    """Comments, string and character literals replaced by spaces; newlines kept."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if not m:
                out.append(c)
                i += 1
                continue
            end = ")" + m.group(1) + '"'
            j = text.find(end, i + m.end())
            j = n if j < 0 else j + len(end)
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            # A digit separator (1'000) is not a character literal.
            if c == "'" and i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum():
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(path):
    """(name, first line, last line) of each function defined in the file."""
    text = blank(open(path, encoding="utf-8", errors="replace").read())
    text = re.sub(r"^[ \t]*#.*$", lambda m: " " * len(m.group(0)), text, flags=re.M)
    found = []
    stack = []  # per open brace: 'scope' (namespace, class, extern), 'function' or 'block'
    head_start = 0  # where the text before the next brace at scope level begins
    line = 1
    open_function = None
    for i, c in enumerate(text):
        if c == "\n":
            line += 1
        if c in ";" and (not stack or stack[-1] == "scope"):
            head_start = i + 1
        elif c == "{":
            inside = any(kind in ("function", "data") for kind in stack)
            if inside:
                stack.append("block")
                continue
            head = text[head_start:i]
            compact = " ".join(head.split())
            if compact.endswith("=") or re.search(r"\)\s*\[\]$|\]\s*$", compact):
                stack.append("data")  # an initialiser: a table, an array
                continue
            if HEAD_NOT_FUNCTION.search(compact) or ")" not in compact:
                stack.append("scope")
                head_start = i + 1
                continue
            name = re.search(r"([~\w:<>]+(?:operator\s*\S+)?)\s*\(", compact)
            # The signature's first line: skip blank lines before the head.
            stripped = head.lstrip()
            first = line - stripped.count("\n")
            open_function = (name.group(1) if name else compact[:40], first)
            stack.append("function")
        elif c == "}":
            kind = stack.pop() if stack else "scope"
            if kind == "function":
                found.append((open_function[0], open_function[1], line))
            if not stack or stack[-1] == "scope":
                head_start = i + 1
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("paths", nargs="*", default=["physics", "app/cli", "app/accuracy", "app/io"])
    parser.add_argument("--limit", type=int, default=150, help="report functions longer than this")
    parser.add_argument("--top", type=int, default=0, help="list the N longest, whatever the limit")
    args = parser.parse_args()
    rows = []
    for root in args.paths:
        walk = [(root, [], [os.path.basename(root)])] if os.path.isfile(root) else os.walk(root)
        for folder, _, files in walk:
            for f in files:
                if f.endswith((".cpp", ".h", ".hpp", ".cc")):
                    path = root if os.path.isfile(root) else os.path.join(folder, f)
                    for name, first, last in functions(path):
                        rows.append((last - first + 1, path, first, name))
    rows.sort(reverse=True)
    shown = rows[: args.top] if args.top else [r for r in rows if r[0] > args.limit]
    for length, path, first, name in shown:
        print(f"{length:5d}  {path}:{first}  {name}")
    return 1 if any(r[0] > args.limit for r in rows) else 0


if __name__ == "__main__":
    sys.exit(main())
