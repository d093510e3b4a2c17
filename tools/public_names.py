#!/usr/bin/env python3
"""Lists the public names that `#include <apse/apse.hpp>` brings into namespace apse (everything
declared directly in `apse::`, not in `apse::detail`), and fails when there are more than --max.

The umbrella header is preprocessed by the C++ compiler (so only what it really includes counts),
then the declarations at the top level of `namespace apse` are read: classes, structs, unions,
enums, aliases, variables and functions (overloads and specialisations of one name count once).

    python3 tools/public_names.py [--compiler g++] [--max N] [--header apse/apse.hpp]
"""
import argparse
import os
import re
import subprocess
import sys

TOKEN = re.compile(r'"(?:\\.|[^"\\])*"|\'(?:\\.|[^\'\\])*\'|[A-Za-z_]\w*|::|->|\d[\w.]*|\S')
KEYWORDS = {"decltype", "noexcept", "sizeof", "alignof", "operator", "static_assert", "return", "if",
            "requires", "alignas", "__attribute__", "__host__", "__device__", "__forceinline__"}


def preprocess(compiler, include, header):
    src = f"#include <{header}>\n"
    return subprocess.run([compiler, "-std=c++17", "-E", "-P", "-I", include, "-x", "c++", "-"],
                          input=src, capture_output=True, text=True, check=True).stdout


def skip_balanced(tokens, i, open_, close):
    """Index after the token that closes the bracket opened at tokens[i]."""
    depth = 0
    while i < len(tokens):
        if tokens[i] == open_:
            depth += 1
        elif tokens[i] == close:
            depth -= 1
            if depth == 0:
                return i + 1
        i += 1
    return i


def skip_template_header(tokens, i):
    """tokens[i] == 'template', tokens[i+1] == '<': index after the matching '>' (brackets and
    parentheses inside are balanced; '>>' closes two)."""
    depth, paren = 0, 0
    i += 1
    while i < len(tokens):
        t = tokens[i]
        if t == "(":
            paren += 1
        elif t == ")":
            paren -= 1
        elif paren == 0 and t == "<":
            depth += 1
        elif paren == 0 and t == ">":
            depth -= 1
            if depth == 0:
                return i + 1
        i += 1
    return i


def declared_name(stmt):
    """The name a namespace-scope declaration (tokens up to its ';' or '{') declares, or None."""
    i = 0
    while i < len(stmt) and stmt[i] == "template":
        i = skip_template_header(stmt, i)
    stmt = stmt[i:]
    k = 0
    while k < len(stmt):  # GNU attributes: __attribute__((...)) anywhere in the declaration
        if stmt[k] == "__attribute__" and k + 1 < len(stmt) and stmt[k + 1] == "(":
            stmt = stmt[:k] + stmt[skip_balanced(stmt, k + 1, "(", ")"):]
        else:
            k += 1
    while stmt[:2] == ["[", "["]:
        stmt = stmt[skip_balanced(stmt, 1, "[", "]") + 1:]
    if not stmt or stmt[0] in ("namespace", "static_assert", "extern"):
        return None
    if stmt[0] == "using":
        return stmt[1] if len(stmt) > 2 and stmt[2] == "=" else None  # aliases; using-declarations
    for k, t in enumerate(stmt):
        if t in ("class", "struct", "union", "enum"):
            j = k + 1
            if j < len(stmt) and stmt[j] in ("class", "struct"):
                j += 1
            return stmt[j] if j < len(stmt) and re.match(r"[A-Za-z_]", stmt[j]) else None
        if t == "(" and k > 0 and stmt[k - 1] not in KEYWORDS and re.match(r"[A-Za-z_]", stmt[k - 1]):
            return stmt[k - 1] if k < 2 or stmt[k - 2] != "::" else None  # out-of-line members
        if t == "(":
            return None
        if t in ("=", "{") and k > 0 and re.match(r"[A-Za-z_]", stmt[k - 1]):
            return stmt[k - 1]
    return stmt[-1] if re.match(r"[A-Za-z_]", stmt[-1]) else None


def public_names(text):
    text = "\n".join(line for line in text.splitlines() if not line.lstrip().startswith("#"))  # pragmas
    tokens = TOKEN.findall(text)
    names, scopes, stmt = set(), [], []
    i = 0
    while i < len(tokens):
        t = tokens[i]
        at_apse = [n for scope in scopes for n in scope] == ["apse"]
        if t == "extern" and i + 2 < len(tokens) and tokens[i + 1].startswith('"') and tokens[i + 2] == "{":
            scopes.append([])  # extern "C" { ... }: a linkage block, not a scope
            stmt = []
            i += 3
            continue
        if t == "namespace":
            j = i + 1
            parts = []
            while tokens[j] != "{" and tokens[j] != "=":
                if tokens[j] != "::":
                    parts.append(tokens[j])
                j += 1
            if tokens[j] == "{":
                scopes.append(parts or [""])
                stmt = []
                i = j + 1
                continue
        if t == "{":
            if at_apse:
                name = declared_name(stmt)
                if name:
                    names.add(name)
            end = skip_balanced(tokens, i, "{", "}")
            i = end
            # a definition's trailing ';' (class) or nothing (function) ends the statement
            stmt = []
            continue
        if t == "}":
            if scopes:
                scopes.pop()
            stmt = []
            i += 1
            continue
        if t == ";":
            if at_apse and stmt:
                name = declared_name(stmt)
                if name:
                    names.add(name)
            stmt = []
            i += 1
            continue
        if t == "(" or t == "[":
            close = ")" if t == "(" else "]"
            end = skip_balanced(tokens, i, t, close)
            stmt.extend(tokens[i:end])
            i = end
            continue
        stmt.append(t)
        i += 1
    return sorted(names)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--compiler", default=os.environ.get("CXX", "g++"))
    ap.add_argument("--include", default=os.path.join(here, "..", "include"))
    ap.add_argument("--header", default="apse/apse.hpp")
    ap.add_argument("--max", type=int, default=None, help="fail when more names than this")
    args = ap.parse_args()
    names = public_names(preprocess(args.compiler, args.include, args.header))
    for n in names:
        print(n)
    print(f"{len(names)} public names in apse:: from <{args.header}>")
    if args.max is not None and len(names) > args.max:
        print(f"FAIL: more than {args.max}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
