#!/usr/bin/env python3
"""Fails listing every function body in Core longer than the limit (200 lines by default).

A function body is the brace block that follows a function signature: a closing parenthesis,
optionally followed by qualifiers (const, noexcept, override, a trailing return type, a
constructor's member initializer list), then an opening brace. Blocks after control keywords
(if, for, while, switch, catch) are statements, not functions; lambdas count as part of the
function that holds them, since a body is measured from its opening to its matching closing
brace whatever it holds. Comments, strings and preprocessor lines are blanked first so that
their braces and parentheses do not count.

Functions named in the exceptions file (default: function_length_exceptions.txt next to this
script; lines "<path relative to the repository> <function>", '#' comments) are reported but
do not fail; an exception that is no longer over the limit is reported as stale.

Usage: check_function_length.py [--limit N] [--self-test] [--exceptions FILE] [paths...]
(default path: the Core folder of the repository holding this script)."""

import argparse
import os
import re
import sys
import tempfile

CONTROL_KEYWORDS = {"if", "for", "while", "switch", "catch", "return", "sizeof", "decltype",
                    "alignof", "noexcept", "static_assert", "defined", "__attribute__"}


def blank_comments_and_strings(text):
    """The text with comments, string and character literals and preprocessor lines replaced
    by spaces (newlines kept, so line numbers stay)."""
    out = []
    i, n = 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if at_line_start and c == "#":
            # Preprocessor line, with its continuations.
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out.append(" \n")
                    i += 2
                    continue
                out.append(" ")
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
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:end]))
            i = end
            continue
        if c == "R" and text.startswith('R"', i) and (i == 0 or not text[i - 1].isalnum()):
            match = re.match(r'R"([^(\s]*)\(', text[i:])
            if match:
                close = ")" + match.group(1) + '"'
                end = text.find(close, i + match.end())
                end = n if end < 0 else end + len(close)
                out.append("".join(ch if ch == "\n" else " " for ch in text[i:end]))
                i = end
                continue
        if c in "\"'":
            # A digit separator (1'000) is not a character literal.
            if c == "'" and i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum():
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(" " * (j - i))
            i = j
            continue
        out.append(c)
        at_line_start = c == "\n" or (at_line_start and c in " \t")
        i += 1
    return "".join(out)


def matching_open_paren(text, close):
    depth = 0
    for i in range(close, -1, -1):
        if text[i] == ")":
            depth += 1
        elif text[i] == "(":
            depth -= 1
            if depth == 0:
                return i
    return -1


def word_before(text, i):
    j = i - 1
    while j >= 0 and text[j].isspace():
        j -= 1
    end = j + 1
    while j >= 0 and (text[j].isalnum() or text[j] in "_:~"):
        j -= 1
    return text[j + 1:end]


def matching_open_brace(text, close):
    depth = 0
    for i in range(close, -1, -1):
        if text[i] == "}":
            depth += 1
        elif text[i] == "{":
            depth -= 1
            if depth == 0:
                return i
    return -1


def skip_space_back(text, j):
    while j >= 0 and text[j].isspace():
        j -= 1
    return j


def name_before(text, open_paren):
    """The name called or declared at the '(' at `open_paren` ("" for a lambda or a cast),
    with "operator" names whole."""
    j = skip_space_back(text, open_paren - 1)
    end = j + 1
    while j >= 0 and text[j] in "=!<>+-*/%&|^~[]":
        j -= 1
    if j + 1 < end:
        word = word_before(text, j + 1)
        return word + text[j + 1:end] if word.endswith("operator") else ""
    return word_before(text, open_paren)


def is_function_body(text, brace):
    """Whether the '{' at `brace` opens a function body (see the module comment): walking
    back, qualifiers and a trailing return type are skipped, a constructor's member
    initializers are passed, and the signature's ')' must follow a name that is no keyword.
    Returns that name, or None."""
    j = brace - 1
    while True:
        j = skip_space_back(text, j)
        if j < 0:
            return None
        c = text[j]
        if c in ")}":
            open_at = matching_open_paren(text, j) if c == ")" else matching_open_brace(text, j)
            if open_at < 0:
                return None
            name = name_before(text, open_at) if c == ")" else word_before(text, open_at)
            if not name or name.split("::")[-1] in CONTROL_KEYWORDS:
                return None
            k = skip_space_back(text, open_at - 1) - len(name.rstrip()) if c == ")" else \
                skip_space_back(text, open_at - 1) - len(name)
            k = skip_space_back(text, k)
            if k >= 0 and (text[k] == "," or (text[k] == ":" and text[k - 1] != ":")):
                j = k - 1  # a member initializer: go on back to the signature
                continue
            return name if c == ")" else None
        if c == ":" and j > 0 and text[j - 1] == ":":
            j -= 2
            continue
        if c.isalnum() or c in "_&*<>-,":
            j -= 1
            continue
        return None


def long_functions(path, limit):
    """(line, length, name) of every function body in `path` longer than `limit` lines."""
    with open(path, encoding="utf-8", errors="replace") as f:
        text = blank_comments_and_strings(f.read())
    found = []
    stack = []  # (position of '{', its function's name when it opens a function body)
    in_function = 0
    for i, c in enumerate(text):
        if c == "{":
            body = is_function_body(text, i) if in_function == 0 else None
            stack.append((i, body))
            if body is not None:
                in_function += 1
        elif c == "}" and stack:
            start, body = stack.pop()
            if body is not None:
                in_function -= 1
                first = text.count("\n", 0, start) + 1
                last = text.count("\n", 0, i) + 1
                length = last - first - 1  # lines strictly between the braces
                if length > limit:
                    found.append((first, length, body))
    return found


def source_files(paths):
    for root in paths:
        if os.path.isfile(root):
            yield root
            continue
        for folder, _, files in os.walk(root):
            for name in sorted(files):
                if name.endswith((".cxx", ".h")):
                    yield os.path.join(folder, name)


SELF_TEST_SOURCE = """
// A comment with a brace { that must not count.
namespace boolsurf
{
struct Holder
{
  int Short() const { return 1; }
};
Holder::Holder(int a)
  : A(a)
  , B{ a }
{
%(constructor)s
}
int LongFunction(int x)
{
  auto lambda = [&](int y)
  {
    if (y > 0)
    {
      return "}";
    }
    return "{";
  };
%(long)s
  return x;
}
template <class T>
T ShortFunction(T x) noexcept
{
  for (int i = 0; i < 3; ++i)
  {
%(short)s
  }
  return x;
}
} // namespace boolsurf
"""


def self_test(limit):
    body = "\n".join("  x += %d;" % i for i in range(limit + 5))
    short = "\n".join("    x += %d;" % i for i in range(limit - 10))
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "Synthetic.cxx")
        with open(path, "w") as f:
            f.write(SELF_TEST_SOURCE % {"long": body, "short": short, "constructor": body})
        found = long_functions(path, limit)
    names = sorted(name for _, _, name in found)
    expected = ["Holder::Holder", "LongFunction"]
    if names != expected:
        print("self-test failed: found %s, expected %s" % (names, expected))
        return False
    print("self-test passed: the synthetic long functions were reported, the short one not")
    return True


def read_exceptions(path):
    """{(repository-relative path, function name)} from an exceptions file (none if absent)."""
    exceptions = set()
    if not os.path.isfile(path):
        return exceptions
    with open(path, encoding="utf-8") as f:
        for line in f:
            words = line.split("#", 1)[0].split()
            if len(words) == 2:
                exceptions.add((words[0], words[1]))
    return exceptions


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--limit", type=int, default=200)
    parser.add_argument("--self-test", action="store_true",
                        help="check the checker on a synthetic source first")
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    parser.add_argument("--exceptions", default=os.path.join(here, "function_length_exceptions.txt"))
    parser.add_argument("paths", nargs="*")
    args = parser.parse_args()
    if args.self_test and not self_test(args.limit):
        return 1
    paths = args.paths or [os.path.join(root, "Core")]
    exceptions = read_exceptions(args.exceptions)
    failures, excepted = [], set()
    for path in source_files(paths):
        relative = os.path.relpath(os.path.abspath(path), root).replace(os.sep, "/")
        for line, length, name in long_functions(path, args.limit):
            message = "%s:%d: %s is %d lines (limit %d)" % (relative, line, name, length,
                                                            args.limit)
            if (relative, name) in exceptions:
                excepted.add((relative, name))
                print(message + " [exception, see %s]" % os.path.basename(args.exceptions))
            else:
                failures.append(message)
    for relative, name in sorted(exceptions - excepted):
        print("stale exception (no longer over the limit, or not checked): %s %s" %
              (relative, name))
    for failure in failures:
        print(failure)
    if failures:
        print("%d function(s) over %d lines" % (len(failures), args.limit))
        return 1
    print("no function over %d lines outside the exceptions" % args.limit)
    return 0


if __name__ == "__main__":
    sys.exit(main())
