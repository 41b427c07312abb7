#!/usr/bin/python3
"""The libraries are compiled as unity batches (docs/robustness.md, "The first build"): several
sources of one library in one translation unit. There, two sources' file-local names meet. The
same name twice is a compile error at best and, for two functions whose parameters differ, a
silent overload that can pick the other source's helper. This check keeps every file-local name
(an anonymous namespace's types, functions, variables and aliases, and file-scope `static`s)
unique within its library, whatever batch the sources land in, and refuses `using namespace` at
file scope in a library source (it would leak into the sources after it). It also keeps the
types of the named namespaces (headers and sources) unique across the program: two classes of one
qualified name in two places break the one-definition rule whether or not a batch joins them.
Prints each clash (the name, its library, the files) and exits 1 if there is one.

Usage: unity_names.py SOURCE_DIR    (after a self-test on planted clashes, which must be found)
"""
import collections
import os
import re
import sys

# The libraries, longest prefix first (dynamics/contact is a library inside dynamics/).
LIBRARIES = ("dynamics/contact", "core", "fracture", "interfaces", "cg", "dg", "dynamics",
             "verification", "python")
KEYWORDS = {"const", "constexpr", "inline", "static", "auto", "void", "int", "double", "bool",
            "char", "unsigned", "long", "std", "operator", "template", "typename", "return",
            "struct", "class", "enum", "union", "using", "namespace", "noexcept", "final",
            "override", "explicit", "size_t", "if", "for", "while", "switch", "sizeof",
            "decltype", "alignas", "thread_local", "extern", "friend", "virtual", "mutable"}
IDENT = re.compile(r"[A-Za-z_]\w*")
TYPE_DECL = re.compile(r"\b(?:struct|class|union|enum(?:\s+class|\s+struct)?)\s+([A-Za-z_][\w:]*)")


def strip(text):
    """The source without comments, string and character literals, or preprocessor lines."""
    text = re.sub(r'R"(\w*)\((?:.|\n)*?\)\1"', '""', text)
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            i = text.find("\n", i)
            i = n if i < 0 else i
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            i = n if j < 0 else j + 2
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append('""')
            i = j + 1
        else:
            out.append(c)
            i += 1
    lines = [ln for ln in "".join(out).split("\n") if not ln.lstrip().startswith("#")]
    return "\n".join(lines)


def without_templates(chunk):
    """The chunk with its leading `template <...>` heads removed."""
    chunk = chunk.strip()
    while chunk.startswith("template"):
        depth, i = 0, chunk.find("<")
        for j in range(i, len(chunk)):
            depth += {"<": 1, ">": -1}.get(chunk[j], 0)
            if depth == 0:
                chunk = chunk[j + 1:].strip()
                break
        else:
            return ""
    return chunk


def declared_names(chunk):
    """The names a namespace-level declaration introduces (best effort, for clash detection)."""
    chunk = without_templates(chunk)
    if not chunk or chunk.startswith(("using namespace", "namespace", "static_assert")):
        return []
    alias = re.match(r"using\s+([A-Za-z_]\w*)\s*=", chunk)
    if alias:
        return [alias.group(1)]
    if chunk.startswith("using "):
        return []
    kind = TYPE_DECL.match(chunk)
    if kind:
        return [kind.group(1)]
    # A variable (`= ...`, or a list `a = 1, b = 2`) or a function (`name(`): the identifier
    # just before the first '=', '(' , '{' or '['.
    head = re.split(r"[=({\[]", chunk, maxsplit=1)[0]
    names = [w for w in IDENT.findall(head) if w not in KEYWORDS]
    found = names[-1:] if names else []
    if "=" in chunk.split("(")[0]:
        found += re.findall(r",\s*([A-Za-z_]\w*)\s*=", chunk)
    return found


def file_local_names(text):
    """(names in anonymous namespaces or declared static at namespace scope, file-scope
    `using namespace` directives, types defined in named namespaces with their qualified names)
    of one source or header."""
    text = strip(text)
    names, usings, types = [], [], []
    stack = []  # one entry per open brace: 'anon', 'body' or the namespace's name
    chunk, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        at_namespace_level = all(s != "body" for s in stack)
        if not at_namespace_level:
            if c == "{":
                stack.append("body")
            elif c == "}":
                stack.pop()
            i += 1
            continue
        if c in ";{}":
            decl = " ".join("".join(chunk).split())
            chunk = []
            in_anonymous = "anon" in stack
            opened = re.fullmatch(r"(?:inline\s+)?namespace(?:\s+([\w:]+))?", decl)
            if c == "}":
                if stack:
                    stack.pop()
            elif c == "{" and opened:
                stack.append(opened.group(1) or "anon")
            else:
                if decl.startswith("using namespace"):
                    usings.append(decl)
                elif in_anonymous or re.match(r"(?:template\s*<.*>\s*)?static\b", decl):
                    names += declared_names(decl)
                elif c == "{" and TYPE_DECL.match(without_templates(decl)):
                    types.append("::".join(stack + [TYPE_DECL.match(without_templates(decl)).group(1)]))
                if c == "{":
                    stack.append("body")
        else:
            chunk.append(c)
        i += 1
    return names, usings, types


def library_of(path):
    for lib in LIBRARIES:
        if path.startswith(lib + "/"):
            return lib
    return None


def main(source_dir):
    owners = collections.defaultdict(set)  # (library, name) -> files
    type_owners = collections.defaultdict(set)  # qualified type name -> files
    breaches = []
    for folder in LIBRARIES:
        for root, _, files in os.walk(os.path.join(source_dir, folder)):
            for name in sorted(files):
                if not name.endswith((".cpp", ".hpp")):
                    continue
                path = os.path.relpath(os.path.join(root, name), source_dir)
                library = library_of(path)
                with open(os.path.join(source_dir, path), encoding="utf-8") as f:
                    names, usings, types = file_local_names(f.read())
                for qualified in set(types):
                    type_owners[qualified].add(path)
                if name.endswith(".hpp"):
                    continue
                for local in set(names):
                    owners[(library, local)].add(path)
                for using in usings:
                    breaches.append(f"{path}: '{using}' at file scope leaks into the next "
                                    "source of a unity batch; qualify the names instead")
    for (library, local), files in sorted(owners.items()):
        if len(files) > 1:
            breaches.append(f"{library}: file-local name '{local}' in {len(files)} sources "
                            f"({', '.join(sorted(files))}); rename one or share it in a header")
    for qualified, files in sorted(type_owners.items()):
        if len(files) > 1:
            breaches.append(f"type '{qualified}' defined in {len(files)} places "
                            f"({', '.join(sorted(files))}): one definition per program")
    for line in breaches:
        print(line)
    return 1 if breaches else 0


PLANTED = {
    "core/a/A.cpp": "namespace vorodg {\nnamespace {\nconstexpr int kShared = 1, kAlso = 2;\n"
                    "template <class T>\nvoid helper(T) {}\nstruct Row { int x; };\n}  // namespace\n"
                    "static double twice(double x) { return 2 * x; }\n"
                    "struct Verdict { int level; };\n}  // namespace vorodg\n",
    "core/b/B.cpp": "// namespace { int kShared; } in a comment is not a declaration\n"
                    "using namespace std;\nnamespace vorodg {\nnamespace {\n"
                    "const char* kAlso = \"namespace { int helper; }\";\n"
                    "double helper(double y) { return y; }\nusing Row = int;\n}  // namespace\n"
                    "static int twice(int x) { return x; }\n}  // namespace vorodg\n",
    "core/b/B.hpp": "#pragma once\nnamespace vorodg {\nenum class Verdict { yes, no };\n}\n",
    "dg/C.cpp": "namespace vorodg {\nnamespace {\nint kShared = 3;\n}\n}\n",
}
EXPECTED = {"'kAlso'", "'helper'", "'Row'", "'twice'", "'vorodg::Verdict'", "'using namespace std'"}


def self_test():
    """The checker finds each planted clash, and not the one across two libraries (kShared in
    core and dg) nor the names inside comments and strings."""
    import contextlib
    import io
    import tempfile
    with tempfile.TemporaryDirectory() as root:
        for path, text in PLANTED.items():
            os.makedirs(os.path.dirname(os.path.join(root, path)), exist_ok=True)
            with open(os.path.join(root, path), "w", encoding="utf-8") as f:
                f.write(text)
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            status = main(root)
    lines = out.getvalue().splitlines()
    found = {e for e in EXPECTED if any(e in line for line in lines)}
    shared = [line for line in lines if "'kShared'" in line]
    if status != 1 or found != EXPECTED or len(lines) != len(EXPECTED) or shared:
        sys.exit(f"unity_names self-test failed: expected {sorted(EXPECTED)}, got {lines}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: unity_names.py SOURCE_DIR")
    self_test()
    sys.exit(main(sys.argv[1]))
