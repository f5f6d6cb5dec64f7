#!/usr/bin/python3
"""McCabe's cyclomatic complexity of every function in the code that ships, read from clang's own
parse of each translation unit (libclang, Debian's python3-clang-14), not from a regex over the text.

  tools/complexity.py BUILD_DIR LIMIT FILE...    (the .cpp files to read; their headers come with them)

A file that is not in BUILD_DIR's compile_commands.json is read as C++20 with no include paths (the
tests' fixtures).

A function's complexity is 1 + its decisions: each if, for, range-for, while, do, case, catch, ?:, &&
and || (what lizard counts; `else if` is one if, `default:` is no decision). A lambda's decisions
count in the function that holds it: a long function cannot hide its branches in closures.
Prints each function over LIMIT as file:line: name complexity N, and exits 1 if there is one.
clang-tidy's readability-function-size counts the statements' branches only (no && || ?:), which is
why this exists beside it.
"""
import json
import multiprocessing
import os
import shlex
import sys

import clang.cindex as ci

DECISIONS = {
    ci.CursorKind.IF_STMT,
    ci.CursorKind.FOR_STMT,
    ci.CursorKind.CXX_FOR_RANGE_STMT,
    ci.CursorKind.WHILE_STMT,
    ci.CursorKind.DO_STMT,
    ci.CursorKind.CASE_STMT,
    ci.CursorKind.CXX_CATCH_STMT,
    ci.CursorKind.CONDITIONAL_OPERATOR,
}
FUNCTIONS = {
    ci.CursorKind.FUNCTION_DECL,
    ci.CursorKind.CXX_METHOD,
    ci.CursorKind.CONSTRUCTOR,
    ci.CursorKind.DESTRUCTOR,
    ci.CursorKind.CONVERSION_FUNCTION,
    ci.CursorKind.FUNCTION_TEMPLATE,
}
ROOT = os.path.realpath(os.path.join(os.path.dirname(__file__), ".."))


def operator_of(binary):
    """The spelling of a binary operator: the first token after its left operand."""
    children = list(binary.get_children())
    if len(children) != 2:
        return ""
    end = children[0].extent.end.offset
    for token in binary.get_tokens():
        if token.extent.start.offset >= end:
            return token.spelling
    return ""


def decisions(cursor):
    count = 0
    for child in cursor.get_children():
        if child.kind in DECISIONS:
            count += 1
        elif child.kind == ci.CursorKind.BINARY_OPERATOR and operator_of(child) in ("&&", "||"):
            count += 1
        count += decisions(child)
    return count


def functions(cursor, found, within):
    for child in cursor.get_children():
        location = child.location
        if location.file is None or not os.path.realpath(location.file.name).startswith(within):
            continue
        if child.kind in FUNCTIONS and child.is_definition():
            path = os.path.relpath(os.path.realpath(location.file.name), ROOT)
            found[(path, location.line, child.spelling)] = 1 + decisions(child)
        else:
            functions(child, found, within)


def arguments_of(entry):
    words = entry["arguments"] if "arguments" in entry else shlex.split(entry["command"])
    kept, skip = [], False
    for word in words[1:]:
        if skip:
            skip = False
        elif word in ("-o", "-c"):
            skip = True
        elif word != entry["file"] and not word.startswith("-W"):
            kept.append(word)
    return kept + ["-Wno-everything"]


def measure(job):
    entry, = job
    os.chdir(entry["directory"])
    arguments = arguments_of(entry) if "command" in entry or "arguments" in entry else ["-xc++", "-std=c++20"]
    unit = ci.Index.create().parse(entry["file"], args=arguments)
    errors = [d for d in unit.diagnostics if d.severity >= ci.Diagnostic.Error]
    if errors:
        return {}, ["%s: clang could not parse it: %s" % (entry["file"], errors[0])]
    found = {}
    # The project's functions (its headers' too, not the system's); a fixture's own, outside it.
    real = os.path.realpath(entry["file"])
    functions(unit.cursor, found, ROOT + os.sep if real.startswith(ROOT + os.sep) else real)
    return found, []


def main():
    build, limit, files = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    entries = {e["file"]: e for e in json.load(open(os.path.join(build, "compile_commands.json")))}
    jobs = [(entries.get(f, {"file": os.path.abspath(f), "directory": os.getcwd()}),) for f in files]
    found, problems = {}, []
    with multiprocessing.Pool(os.cpu_count()) as pool:
        for part, trouble in pool.imap_unordered(measure, jobs):
            found.update(part)
            problems += trouble
    over = sorted((value, key) for key, value in found.items() if value > limit)
    for value, (path, line, name) in reversed(over):
        print("%s:%d: %s complexity %d (limit %d)" % (path, line, name, value, limit))
    for problem in problems:
        print(problem)
    print("complexity: %d functions read, %d over %d" % (len(found), len(over), limit), file=sys.stderr)
    return 1 if over or problems else 0


if __name__ == "__main__":
    sys.exit(main())
