"""The mutation classes of issue 14's experiment (docs/robustness.md, "The mutation harness").

Each generator takes one file's text and yields (description, make, line): make() returns the
mutant (built only for the mutants a sample keeps), line is the 1-based line of the mutated value
in the mutant (None when the mutant is re-serialised).
(a) delete_key, (b) swap_type, (c) numbers: YAML scenes (PyYAML's node tree: scalars are spliced
into the original text, so every other line stays where it was; deletions and list/map -> scalar
re-serialise the tree); (c) mesh_numbers, (d) random: any file, bytes.
"""
import functools
import re

import yaml

NUMBER = re.compile(r"^[-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?$")
NUMBER_VALUES = ["-1", "0", ".nan", ".inf", "-.inf", "1e300", "1e-300"]
MESH_NUMBER_VALUES = ["-1", "0", "nan", "inf", "-inf", "1e300", "1e-300"]
# bytes a random insertion picks from: YAML's indicators, digits, letters, white space, controls
SPECIAL = b":-[]{}&*!|>'\"%@`#,?~\n\t 0123456789.eE+xyz\x00\xff"


# (text) => the document's node tree, or None when PyYAML cannot compose it
def compose(text):
    try:
        return yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.YAMLError:
        return None


# (node tree) => (path, parent, index, node) for every value position, each node once
def walk(root):
    seen = set()
    stack = [("", None, None, root)]
    while stack:
        path, parent, index, node = stack.pop()
        if id(node) in seen:
            continue
        seen.add(id(node))
        yield path, parent, index, node
        if isinstance(node, yaml.MappingNode):
            for i, (k, v) in reversed(list(enumerate(node.value))):
                name = k.value if isinstance(k, yaml.ScalarNode) else "?"
                stack.append((f"{path}.{name}" if path else name, node, i, v))
        elif isinstance(node, yaml.SequenceNode):
            for i, v in reversed(list(enumerate(node.value))):
                stack.append((f"{path}[{i}]", node, i, v))


# (node tree) => the YAML text of the tree (anchors where a node is shared)
def serialize(root):
    return yaml.serialize(root, Dumper=yaml.SafeDumper, width=100000, allow_unicode=True)


# (text, scalar node) => [start, end) of the scalar's own text (past an anchor or a tag)
def scalar_span(text, node):
    start, end = node.start_mark.index, node.end_mark.index
    while start < end and text[start] in "&!":
        while start < end and not text[start].isspace():
            start += 1
        while start < end and text[start] in " \t":
            start += 1
    return start, end


def is_number(node):
    return isinstance(node, yaml.ScalarNode) and node.style is None and NUMBER.match(node.value)


def replaced(text, start, end, new):
    return text[:start] + new + text[end:]


# (text, node, replacement) => make() of the text with the scalar replaced, and the replacement's
# line
def splice(text, node, new):
    start, end = scalar_span(text, node)
    return functools.partial(replaced, text, start, end, new), text.count("\n", 0, start) + 1


# (tree, mapping, index) => the tree's text without the mapping's index-th pair
def without_pair(root, node, i):
    pair = node.value.pop(i)
    try:
        return serialize(root)
    finally:
        node.value.insert(i, pair)


# (tree, parent, index) => the tree's text with the parent's index-th value the scalar 7
def as_scalar(root, parent, index):
    old = parent.value[index]
    scalar = yaml.ScalarNode("tag:yaml.org,2002:int", "7")
    parent.value[index] = (old[0], scalar) if isinstance(parent, yaml.MappingNode) else scalar
    try:
        return serialize(root)
    finally:
        parent.value[index] = old


# (a) (text) => the document with each mapping key deleted in turn
def delete_key(text):
    root = compose(text)
    if root is None:
        return
    for path, _, _, node in walk(root):
        if not isinstance(node, yaml.MappingNode):
            continue
        for i, (k, _) in enumerate(node.value):
            key = k.value if isinstance(k, yaml.ScalarNode) else "?"
            yield f"delete {path + '.' if path else ''}{key}", functools.partial(without_pair, root, node, i), None


# (b) (text) => each scalar as another type (number -> string, list, map; string -> list, map),
# each list and map (but the root) as a scalar
def swap_type(text):
    root = compose(text)
    if root is None:
        return
    for path, parent, index, node in walk(root):
        if isinstance(node, yaml.ScalarNode):
            news = ["abc", "[1, 2]", "{a: 1}"] if is_number(node) else ["[x, y]", "{a: 1}"]
            for new in news:
                mutated, line = splice(text, node, new)
                yield f"{path}: {node.value!r} -> {new}", mutated, line
        elif parent is not None:
            kind = "map" if isinstance(node, yaml.MappingNode) else "list"
            yield f"{path}: {kind} -> 7", functools.partial(as_scalar, root, parent, index), None


# (c) (text) => every number replaced by -1, 0, .nan, .inf, -.inf, 1e300, 1e-300 (integers also
# by 2.5)
def numbers(text):
    root = compose(text)
    if root is None:
        return
    for path, _, _, node in walk(root):
        if not is_number(node):
            continue
        integer = not re.search(r"[.eE]", node.value)
        for new in NUMBER_VALUES + (["2.5"] if integer else []):
            mutated, line = splice(text, node, new)
            yield f"{path}: {node.value} -> {new}", mutated, line


# (c, meshes) (text, rng, count) => `count` sampled numbers of an OBJ/ASCII STL file replaced
def mesh_numbers(text, rng, count):
    spans = [m.span() for m in re.finditer(r"(?<![\w.])[-+]?\d+(\.\d*)?([eE][-+]?\d+)?(?![\w.])", text)]
    for start, end in sorted(rng.sample(spans, min(count, len(spans)))):
        old = text[start:end]
        integer = not re.search(r"[.eE]", old)
        line = text.count("\n", 0, start) + 1
        for new in MESH_NUMBER_VALUES + (["2.5"] if integer else []):
            yield f"line {line}: {old} -> {new}", functools.partial(replaced, text, start, end, new), line


# (d) (bytes, rng, count) => `count` mutants, each with 1 to 3 of: a bit flipped, a byte inserted,
# bytes deleted, a line duplicated
def random_bytes(data, rng, count):
    for _ in range(count):
        out = bytearray(data)
        ops = []
        for _ in range(rng.randint(1, 3)):
            op = rng.choice(["flip", "insert", "delete", "dupline"])
            at = rng.randrange(max(len(out), 1))
            if op == "flip" and out:
                out[at] ^= 1 << rng.randrange(8)
            elif op == "insert":
                out[at:at] = bytes([rng.choice(SPECIAL)])
            elif op == "delete":
                del out[at:at + rng.randint(1, 8)]
            else:
                start = out.rfind(b"\n", 0, at) + 1
                end = out.find(b"\n", at)
                end = len(out) if end < 0 else end + 1
                out[end:end] = out[start:end]
            ops.append(f"{op}@{at}")
        yield " ".join(ops), functools.partial(bytes, out), None
