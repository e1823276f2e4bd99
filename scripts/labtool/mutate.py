"""Single-point mutants of the solution lines of one task block: the wrong answers a student writes.

Each mutant changes one place: a relational operator (< <=, > >=, == !=), && and ||, + and -
(also += -=), a unary minus dropped, std::abs dropped (-std::abs(v) becomes -v), std::min and
std::max swapped, a constant changed (a number, true/false), a statement dropped (an assignment,
a call, a break/continue/return), a break added inside a loop. The tokenizer knows strings,
characters and comments, so nothing inside them is touched. Not tried: < to <= in a for
header (one past the end is undefined behaviour, which CI's sanitizer build is there to see).

A mutant is keyed by what it changes, not by its line number, so a list of equivalent mutants
(tests/labs/equivalent-mutants.txt) survives edits elsewhere in the file: (file, task, the
original line, the mutated line, which occurrence of that pair in the task).
"""
import re
from dataclasses import dataclass

TOKEN = re.compile(
    r"""(?P<space>\s+)
      | (?P<comment>//.*)
      | (?P<string>"(?:\\.|[^"\\])*"|'(?:\\.|[^'\\])*')
      | (?P<number>(?:\d+\.\d*|\.\d+|\d+)(?:[eE][+-]?\d+)?[fFuUlL]*)
      | (?P<name>[A-Za-z_]\w*)
      | (?P<punct>::|->|\+\+|--|<<=|>>=|<<|>>|<=|>=|==|!=|&&|\|\||\+=|-=|\*=|/=|[-+*/%<>=!&|^~?:;,.(){}\[\]])
    """,
    re.VERBOSE,
)
# A declaration's first words: dropping a declaration only fails to compile, so it is not tried.
DECLARATION_START = re.compile(
    r"^\s*(const|constexpr|static|auto|float|double|int|bool|unsigned|char|long|std::size_t|"
    r"std::vector|std::optional|std::array|sf::\w+|hitbox::\w+|[A-Z]\w*)\b"
)
# Tokens after which a '-' is unary (a sign), not a subtraction.
UNARY_AFTER = {"(", "[", "{", ",", "=", "return", "?", ":", "<", ">", "<=", ">=", "==", "!=", "+", "-",
               "*", "/", "&&", "||", "+=", "-=", "*=", "/=", "!"}


@dataclass
class Mutant:
    """One changed task block: the file's new text and how it differs from the solution."""

    file: str  # repository-relative path of the mutated source
    task: int
    line: int  # 1-based line of the change (for the report only; keys never use it)
    kind: str  # relational, logical, arithmetic, sign, abs, minmax, constant, drop, break
    original: str  # the line as written (stripped)
    mutated: str  # the line after the change (stripped; "" when it was dropped)
    occurrence: int = 1  # nth mutant of this task with the same original and mutated line
    text: str = ""  # the whole mutated file

    def key(self):
        return (self.file, self.task, self.original, self.mutated, self.occurrence)


def tokens(line):
    """(kind, text, start) for every token of one line, blanks left out; None if it cannot tokenize."""
    found, at = [], 0
    while at < len(line):
        match = TOKEN.match(line, at)
        if not match:
            return None
        if match.lastgroup != "space":
            found.append((match.lastgroup, match.group(), at))
        at = match.end()
    return found


def _template_brackets(toks):
    """Indexes of < and > that open or close a template argument list (vector<int>), not comparisons."""
    skip = set()
    for i, (kind, text, _) in enumerate(toks):
        if text != "<" or i == 0 or toks[i - 1][0] != "name":
            continue
        depth, j = 1, i + 1
        while j < len(toks) and depth:
            t = toks[j][1]
            if t == "<":
                depth += 1
            elif t == ">":
                depth -= 1
            elif t not in ("::", ",", "*", "&") and toks[j][0] not in ("name", "number"):
                break
            j += 1
        if depth == 0:
            skip.update({i, j - 1})
    return skip


def _replace(line, start, old, new):
    return line[:start] + new + line[start + len(old):]


def line_mutations(line):
    """(kind, new line) for every single-token change of one code line."""
    toks = tokens(line)
    if not toks or line.lstrip().startswith("#"):
        return []
    templates = _template_brackets(toks)
    # "for (i = 0; i < n; ++i)" with <= reads one past the end: undefined behaviour, which a
    # test may or may not see (CI's sanitizer build is where it shows), so it is not tried.
    for_header = toks[0][1] == "for"
    swaps = {"<": "<=", "<=": "<", ">": ">=", ">=": ">", "==": "!=", "!=": "==",
             "&&": "||", "||": "&&", "+=": "-=", "-=": "+="}
    found = []
    for i, (kind, text, start) in enumerate(toks):
        before = toks[i - 1][1] if i else ""
        if kind == "punct":
            if text == "<" and for_header:
                continue
            if text in swaps and i not in templates:
                what = "logical" if text in ("&&", "||") else "arithmetic" if "=" in text and text[0] in "+-" else "relational"
                found.append((what, _replace(line, start, text, swaps[text])))
            elif text in ("+", "-") and before not in UNARY_AFTER and i > 0:
                found.append(("arithmetic", _replace(line, start, text, "-" if text == "+" else "+")))
            elif text == "-" and (i == 0 or before in UNARY_AFTER):
                found.append(("sign", line[:start] + line[start + 1:]))
        elif kind == "name":
            if text in ("true", "false"):
                found.append(("constant", _replace(line, start, text, "false" if text == "true" else "true")))
            elif text == "abs" and before == "::" and i + 1 < len(toks) and toks[i + 1][1] == "(":
                # std::abs(v) -> (v): the sign flip a student writes instead of the absolute value.
                qualified = toks[i - 2][2] if i >= 2 and toks[i - 2][1] == "std" else toks[i - 1][2]
                found.append(("abs", line[:qualified] + line[toks[i + 1][2]:]))
            elif text in ("min", "max") and before == "::":
                found.append(("minmax", _replace(line, start, text, "max" if text == "min" else "min")))
        elif kind == "number":
            found.append(("constant", _replace(line, start, text, _changed_number(text))))
    return found


def _changed_number(text):
    """A different constant of the same type: an integer plus one, a float plus one (0.5f -> 1.5f)."""
    body = text.rstrip("fFuUlL")
    suffix = text[len(body):]
    if re.fullmatch(r"\d+", body):
        return str(int(body) + 1) + suffix
    value = float(body) + 1.0
    written = repr(value)
    if "e" not in written and "." not in written:
        written += ".0"
    return written + suffix


def _statements(lines):
    """(first index, last index) of each complete statement that ends with ';' at bracket depth 0."""
    found, start, depth = [], None, 0
    for index, line in enumerate(lines):
        toks = tokens(line) or []
        code = [t for t in toks if t[0] != "comment"]
        if not code:
            continue
        if start is None:
            start = index
        for _, text, _ in code:
            if text in "([{":
                depth += 1
            elif text in ")]}":
                depth -= 1
        if code[-1][1] in ("{", "}") or depth < 0:
            start, depth = None, 0
            continue
        if depth == 0 and code[0][1] in ("if", "for", "while", "else") and code[-1][1] in (")", "else"):
            start = None  # a control line: the statement it guards starts on the next line
            continue
        if code[-1][1] == ";" and depth == 0:
            found.append((start, index))
            start = None
    return found


def _droppable(first_line):
    """A statement whose absence still compiles: an assignment, a call, a jump (not a declaration)."""
    text = first_line.strip()
    if re.match(r"^(break|continue|return)\b", text):
        return True
    if re.match(r"^(if|for|while|else|do|switch|case)\b", text):
        return False
    if DECLARATION_START.match(text) and not re.match(r"^[A-Z]\w*(::\w+)*\s*\(", text):
        # "Foo bar = ..." declares; "Collision::check(...)" is a call.
        if not re.match(r"^[A-Za-z_][\w:]*(\.|->|\[)", text):
            return False
    return bool(re.match(r"^[+\-]*[\w:.\->\[\]*()]+\s*(=|\+=|-=|\*=|/=|\(|\+\+|--)", text) or re.match(r"^(\+\+|--)\w", text))


def mutants_of_region(path, relative, region, lines):
    """Every mutant of one task block; `lines` is the file as a list of lines (no line ends)."""
    found = []

    def add(kind, number, new_lines, original, mutated):
        changed = list(lines)
        for at, text in new_lines.items():
            changed[at - 1] = text
        found.append(Mutant(relative, region.task, number, kind, original.strip(), mutated.strip(),
                            text="\n".join(changed) + "\n"))

    for number, text in region.solution_lines:
        for kind, new in line_mutations(text):
            add(kind, number, {number: new}, text, new)

    numbers = [n for n, _ in region.solution_lines]
    texts = [t for _, t in region.solution_lines]
    for first, last in _statements(texts):
        if _droppable(texts[first]):
            dropped = {numbers[i]: "" for i in range(first, last + 1)}
            add("drop", numbers[first], dropped, texts[first], "")
    # A break added after the first statement of each loop body: stopping a search early.
    loops = []  # [brace depth of the loop body, break already added]
    depth, pending_loop = 0, False
    for index, text in enumerate(texts):
        stripped = text.strip()
        if re.match(r"^(for|while)\b", stripped):
            pending_loop = True
        for _, tok, _ in tokens(text) or []:
            if tok == "{":
                depth += 1
                if pending_loop:
                    loops.append([depth, False])
                    pending_loop = False
            elif tok == "}":
                if loops and loops[-1][0] == depth:
                    loops.pop()
                depth -= 1
        if loops and not loops[-1][1] and depth == loops[-1][0] and stripped.endswith(";") \
                and not re.match(r"^(break|continue|return)\b", stripped):
            add("break", numbers[index], {numbers[index]: text + " break;"}, text, stripped + " break;")
            loops[-1][1] = True
    # Number repeats so every key is unique.
    seen = {}
    for mutant in found:
        pair = (mutant.original, mutant.mutated)
        seen[pair] = seen.get(pair, 0) + 1
        mutant.occurrence = seen[pair]
    return found
