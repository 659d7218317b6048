"""Library source (the GLSL subset of the node libraries) -> untyped IR (code/ir.py).

What it takes: structs, `const` globals, plain globals and `uniform` declarations (an ir.Global of
kind "uniform": the generator declares it as the stage's), functions (prototypes are skipped:
the IR needs none), `#define NAME value` (a Constant; `#define NAME TYPE` too, which the checker
takes for a type alias), `#include "file"` (Module.includes, resolved relative to the file),
`#pragma shadergen feature ...` (Module.features), and `#ifdef`/`#ifndef`/`#else`/`#endif` around
items and statements (ir.Section). A section may also hold the `else` or `else if` of the `if`
before it:

    if (a) {...}
    #ifdef T
    else if (t) {...}
    #endif
    #ifdef L
    else {...}
    #endif

The `if`'s `other` is then an unscoped Block holding the section (`else_branch`); whatever follows
the section continues the chain on both of its sides (the clause after it is parsed into each), so
every combination of macros reads as the preprocessor would give it.

Which identifiers are types is not known here (structs come from included files): `A B` at the
start of a statement is a declaration, `vec3(...)` of a GLSL type a Construct, and a call of any
other name a Call, which the checker turns into a Construct where the name is a struct or alias.
An array size is kept as its source (`T[3]`, `T[MAX_LIGHT_SOURCES]`) for the checker to settle.

Comments: those on lines of their own become ir.Comment statements in bodies and the `comment`
of the item below them at the top level (a top-level block a blank line separates from what
follows documents the file, or a part of it, and is dropped); one after code on its line is the
`comment` of the statement it ends (or, after `{`, `)` or `else`, of the statement it starts).
Comments inside expressions are dropped. Brace-less bodies are `Block(..., scoped=False)`.
"""
import copy
import os
import re

from ..errors import source_error
from . import ir
from .lex import Token, tokenize
from .types import GLSL_TYPES

# `#pragma shadergen feature NAME [unless INPUT OP VALUE]` (features.py says what it means). The
# patterns here are sources, compiled (and kept in re's cache) where a source is parsed: a process
# that reads its library from the cache parses nothing, and compiling them was 0.9 ms of its start.
DECLARATION = r"^\s*#\s*pragma\s+shadergen\s+feature\s+(\w+)(?:\s+unless\s+(\w+)\s*(==|!=|<=|>=|<|>)\s*(\S+))?\s*$"

__all__ = ["parse_module", "parse_expression"]

BINARY = (("||",), ("&&",), ("|",), ("^",), ("&",), ("==", "!="), ("<", ">", "<=", ">="), ("<<", ">>"),
          ("+", "-"), ("*", "/", "%"))  # loosest first
PRECEDENCE = {op: level for level, ops in enumerate(BINARY) for op in ops}
ASSIGN = frozenset({"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>="})
QUALIFIERS = frozenset({"in", "out", "inout", "const"})
DIRECTIVE = r"#\s*(\w*)\s*(.*)$"
INCLUDE = r'"([^"]+)"$'
DEFINE = r"(\w+)(?:\s+(.*))?$"
SECTION_OPEN = frozenset({"ifdef", "ifndef"})
SECTION_CLOSE = frozenset({"else", "endif"})
# Bounds on what a source may nest, so that the recursive parser, checker, printers and copies stay
# well inside Python's recursion limit (a document's own inline expression is read with these
# too): parentheses, calls and blocks inside each other, and the height of the tree it makes
# (`a + a + ... + a` is read by a loop but makes a tree as high as it is long). The library's
# highest expression is 11 nodes high.
MAX_NESTING = 40
MAX_HEIGHT = 128


def parse_module(path: str, text: str) -> ir.Module:
    """One library source file as an ir.Module (untyped: code/check.py types it)."""
    module = Parser(path, tokenize(path, text)).module()
    for item in module.items:
        check_height(item, path)
    return module


def parse_expression(text: str, where: str) -> ir.Expr:
    """An inline implementation's expression (`{{name}}` an ir.Placeholder); `where` names it in errors."""
    parser = Parser(where, tokenize(where, text, placeholders=True))
    expr = parser.expression()
    if parser.peek().kind != "eof":
        raise parser.error(f"unexpected '{parser.peek().text}' after the expression")
    check_height(expr, where)
    return expr


def check_height(node: ir.Node, path: str) -> None:
    """Refuses a tree higher than MAX_HEIGHT (walked without recursion)."""
    stack = [(node, 1)]
    while stack:
        n, height = stack.pop()
        if height > MAX_HEIGHT:
            where = n.where or (path, 1, 1)
            raise source_error(where[0], where[1], where[2], f"code nested more than {MAX_HEIGHT} deep")
        stack.extend((child, height + 1) for child in ir.children(n))


def directive(tok: Token) -> tuple[str, str]:
    """(`ifdef`, `MACRO`) of a preprocessor line."""
    m = re.match(DIRECTIVE, tok.text)
    return m.group(1), m.group(2).strip()


class Parser:
    def __init__(self, path: str, tokens: list[Token]):
        self.path = path
        self.t: list[Token] = []
        # gap index (the token it precedes) -> the comment tokens there
        self.gaps: dict[int, list[Token]] = {}
        for tok in tokens:
            if tok.kind in ("comment", "trailing"):
                self.gaps.setdefault(len(self.t), []).append(tok)
            else:
                self.t.append(tok)
        self.i = 0
        self.last = len(self.t) - 1  # the eof token's index
        self.claimed: set[int] = set()  # gaps whose trailing comment a statement has taken
        self.nesting = 0  # levels of expressions and blocks now open (MAX_NESTING)
        # the #endif before a dangling else's clause -> (the token after the clause, the clause)
        self.dangling: dict[int, tuple[int, ir.Block]] = {}

    # -- tokens ------------------------------------------------------------------------------------
    def peek(self, k: int = 0) -> Token:
        i = self.i + k
        return self.t[i] if i < self.last else self.t[-1]

    def next(self) -> Token:
        tok = self.peek()
        if tok.kind == "eof":
            raise self.error("unexpected end of source")
        self.i += 1
        return tok

    def at(self, text: str, k: int = 0) -> bool:
        tok = self.peek(k)
        return tok.text == text and tok.kind in ("op", "id")

    def expect(self, text: str) -> Token:
        tok = self.peek()
        if not self.at(text):
            raise self.error(f"expected '{text}', found '{tok.text or 'end of source'}'")
        return self.next()

    def identifier(self) -> Token:
        tok = self.peek()
        if tok.kind != "id":
            raise self.error(f"expected a name, found '{tok.text or 'end of source'}'")
        return self.next()

    def error(self, what: str, tok: Token | None = None):
        tok = tok or self.peek()
        return source_error(self.path, tok.line, tok.column, what)

    def where(self, tok: Token) -> tuple[str, int, int]:
        return (self.path, tok.line, tok.column)

    def at_directive(self, names: frozenset, k: int = 0) -> bool:
        tok = self.peek(k)
        return tok.kind == "pp" and directive(tok)[0] in names

    # -- comments ----------------------------------------------------------------------------------
    def ends_statement(self) -> bool:
        """Whether the token before the current gap ended a statement (`;` or `}`)."""
        return self.i > 0 and self.t[self.i - 1].kind == "op" and self.t[self.i - 1].text in (";", "}")

    def own_line_comments(self) -> list[ir.Stmt]:
        """The comments on lines of their own before the next token, as Comment statements (a
        blank line starts another)."""
        out: list[ir.Comment] = []
        for tok in self.gaps.get(self.i, ()):
            if tok.kind != "comment":
                continue
            if out and not tok.blank and tok.line == out[-1].where[1] + len(out[-1].lines):
                out[-1].lines.append(tok.text)
            else:
                out.append(ir.Comment([tok.text], where=self.where(tok)))
        return out

    def leading_trailing(self) -> str | None:
        """A comment after code on its line, before the next token, where that code did not end
        a statement (after `{`, `)`, `else`): it belongs to the statement that follows."""
        if self.ends_statement():
            return None
        return self.trailing_here()

    def trailing_here(self) -> str | None:
        """The comment after code at the current gap, unless a statement took it already (the
        innermost of those ending there: `if (c) return;  // x` is the return's)."""
        if self.i in self.claimed:
            return None
        texts = [tok.text for tok in self.gaps.get(self.i, ()) if tok.kind == "trailing"]
        if not texts:
            return None
        self.claimed.add(self.i)
        return " ".join(texts)

    def item_comment(self, pending: list[Token]) -> list[Token]:
        """The top-level comments above the next token, after `pending` ones: a blank line drops
        those before it."""
        for tok in self.gaps.get(self.i, ()):
            if tok.kind != "comment":
                continue
            if tok.blank:
                pending = []
            pending = pending + [tok]
        return [] if self.peek().blank else pending

    def nested(self):
        """One level deeper (an expression, block or prefix operator inside another)."""
        self.nesting += 1
        if self.nesting > MAX_NESTING:
            raise self.error(f"code nested more than {MAX_NESTING} deep")

    # -- expressions -------------------------------------------------------------------------------
    def expression(self) -> ir.Expr:
        self.nested()
        cond = self.binary(0)
        if self.at("?"):
            tok = self.next()
            if_true = self.expression()
            self.expect(":")
            cond = ir.Select(cond, if_true, self.expression(), where=self.where(tok))
        self.nesting -= 1
        return cond

    def binary(self, loosest: int) -> ir.Expr:
        """Operators binding at least as tightly as level `loosest` (BINARY), left to right."""
        left = self.unary()
        while True:
            tok = self.peek()
            level = PRECEDENCE.get(tok.text) if tok.kind == "op" else None
            if level is None or level < loosest:
                return left
            self.next()
            left = ir.Binary(tok.text, left, self.binary(level + 1), where=left.where)

    def unary(self) -> ir.Expr:
        tok = self.peek()
        if tok.kind == "op" and tok.text in ("-", "+", "!", "~"):
            self.next()
            self.nested()
            operand = self.unary()
            self.nesting -= 1
            return operand if tok.text == "+" else ir.Unary(tok.text, operand, where=self.where(tok))
        if tok.kind == "op" and tok.text in ("++", "--"):
            raise self.error(f"'{tok.text}' inside an expression")
        return self.postfix(self.primary())

    def primary(self) -> ir.Expr:
        tok = self.next()
        where = self.where(tok)
        if tok.kind == "num":
            return number(tok, where)
        if tok.kind == "placeholder":
            return ir.Placeholder(tok.text, where=where)
        if tok.kind == "op" and tok.text == "(":
            e = self.expression()
            self.expect(")")
            return e
        if tok.kind != "id":
            raise self.error(f"unexpected '{tok.text}'", tok)
        if tok.text in ("true", "false"):
            return ir.Literal(tok.text == "true", tok.text, where=where)
        if self.at("[") and self.array_constructor_ahead():
            size = self.array_suffix()
            args = self.arguments()
            return ir.Construct(f"{tok.text}[{size or len(args)}]", args, where=where)
        if self.at("("):
            args = self.arguments()
            if tok.text in GLSL_TYPES:
                return ir.Construct(tok.text, args, where=where)
            return ir.Call(tok.text, args, where=where)
        return ir.Name(tok.text, None, where=where)

    def array_constructor_ahead(self) -> bool:
        """Whether `[...]` at the next token is followed by `(`: `float[3](...)`."""
        depth, k = 0, 0
        while True:
            tok = self.peek(k)
            if tok.kind == "eof":
                return False
            if tok.kind == "op" and tok.text == "[":
                depth += 1
            elif tok.kind == "op" and tok.text == "]":
                depth -= 1
                if depth == 0:
                    return self.at("(", k + 1)
            k += 1

    def array_suffix(self) -> str:
        """`[N]` (N an integer or a constant's name) as its text; `[]` as ""."""
        self.expect("[")
        if self.at("]"):
            self.next()
            return ""
        tok = self.next()
        if tok.kind == "num" and tok.text.isdigit() or tok.kind == "id":
            self.expect("]")
            return tok.text
        raise self.error("an array size must be an integer or a constant's name", tok)

    def arguments(self) -> list[ir.Expr]:
        self.expect("(")
        args: list[ir.Expr] = []
        if self.at("void") and self.at(")", 1):
            self.next()
        while not self.at(")"):
            args.append(self.expression())
            if not self.at(")"):
                self.expect(",")
        self.expect(")")
        return args

    def postfix(self, e: ir.Expr) -> ir.Expr:
        while True:
            if self.at("."):
                self.next()
                name = self.identifier()
                if self.at("("):
                    raise self.error(f"the method '.{name.text}()'", name)
                e = ir.Field(e, name.text, where=e.where)
            elif self.at("["):
                self.next()
                index = self.expression()
                self.expect("]")
                e = ir.Index(e, index, where=e.where)
            else:
                return e

    # -- statements --------------------------------------------------------------------------------
    def statement_list(self, closes) -> list[ir.Stmt]:
        """Statements up to a token `closes` accepts (not taken), own-line comments among them."""
        out: list[ir.Stmt] = []
        while True:
            out.extend(self.own_line_comments())
            if closes(self):
                return out
            if self.peek().kind == "pp":
                out.append(self.section(lambda stop: self.statement_list(stop)))
            else:
                out.extend(self.statement())

    def section(self, body_of) -> ir.Section:
        """`#ifdef M ... [#else ...] #endif`; `body_of(stop)` reads what is between."""
        tok = self.next()
        name, macro = directive(tok)
        if name not in SECTION_OPEN or not re.fullmatch(r"\w+", macro):
            raise self.error(f"preprocessor line '{tok.text}' here", tok)

        def stop(parser):
            return parser.at_directive(SECTION_CLOSE) or parser.peek().kind == "eof"
        self.nested()
        body = body_of(stop)
        other: list = []
        if self.at_directive(frozenset({"else"})):
            self.next()
            other = body_of(stop)
        self.nesting -= 1
        endif = self.i
        self.close_section(tok)
        if endif in self.dangling:  # an else of the body's last if, after the #endif
            self.i, clause = self.dangling.pop(endif)
            other.append(copy.deepcopy(clause))
        return ir.Section(macro, name == "ifdef", body, other, where=self.where(tok))

    def close_section(self, opened: Token) -> None:
        if not self.at_directive(frozenset({"endif"})):
            raise self.error(f"'{opened.text}' at line {opened.line} has no #endif here")
        self.next()

    def block(self) -> ir.Block:
        tok = self.expect("{")
        self.nested()
        body = self.statement_list(lambda p: p.at("}") or p.peek().kind == "eof")
        self.expect("}")
        self.nesting -= 1
        return ir.Block(body, True, where=self.where(tok))

    def body(self) -> ir.Block:
        """A branch or loop body: a `{}` block, or one statement as an unscoped Block."""
        if self.at("{"):
            lead = self.leading_trailing()
            block = self.block()
            block.comment = self.trailing_here() or lead
            return block
        where = self.where(self.peek())
        comments = self.own_line_comments()
        self.nested()
        body = comments + self.statement()
        self.nesting -= 1
        return ir.Block(body, False, where=where)

    def statement(self) -> list[ir.Stmt]:
        """One statement (several Declares for `T a, b;`), its comments attached."""
        lead = self.leading_trailing()
        stmts = self.one_statement()
        trailing = self.trailing_here()
        if trailing or lead:
            stmts[-1].comment = " ".join(c for c in (lead, trailing) if c)
        return stmts

    def one_statement(self) -> list[ir.Stmt]:
        tok = self.peek()
        where = self.where(tok)
        if self.at("{"):
            return [self.block()]
        if self.at("if"):
            return [self.if_statement()]
        if self.at("for"):
            self.next()
            self.expect("(")
            init = None if self.at(";") else self.simple(single=True)
            self.expect(";")
            cond = None if self.at(";") else self.expression()
            self.expect(";")
            update = None if self.at(")") else self.simple(single=True)
            if isinstance(update, ir.Declare):
                raise self.error("a declaration as a for loop's update", tok)
            self.expect(")")
            return [ir.For(init, cond, update, self.body(), where=where)]
        if self.at("while"):
            self.next()
            self.expect("(")
            cond = self.expression()
            self.expect(")")
            return [ir.While(cond, self.body(), where=where)]
        if self.at("return"):
            self.next()
            value = None if self.at(";") else self.expression()
            self.expect(";")
            return [ir.Return(value, where=where)]
        for word, node in (("break", ir.Break), ("continue", ir.Continue), ("discard", ir.Discard)):
            if self.at(word):
                self.next()
                self.expect(";")
                return [node(where=where)]
        if self.at("else"):
            raise self.error("'else' without an 'if'")
        stmts = self.simple()
        self.expect(";")
        return stmts

    def if_statement(self) -> ir.If:
        tok = self.expect("if")
        self.nested()  # an else-if chain is read by recursion
        self.expect("(")
        cond = self.expression()
        self.expect(")")
        then = self.body()
        stmt = ir.If(cond, then, self.else_tail(), where=self.where(tok))
        self.nesting -= 1
        return stmt

    def else_tail(self) -> ir.Block | None:
        """What follows an `if`'s body: its `else` clause, a section holding one, or nothing."""
        if self.at("else"):
            self.next()
            if self.at_directive(frozenset({"endif"})):
                return self.dangling_else()
            return self.else_clause()
        if self.at_directive(SECTION_OPEN) and self.at("else", 1):
            tok = self.peek()
            return ir.Block([self.else_section()], False, where=self.where(tok))
        return None

    def dangling_else(self) -> ir.Block:
        """`#ifdef M if (c) {...} else #endif {...}`: the else clause is the statement after the
        section, which is also what the section's other side is followed by (section() adds it
        there and goes on after it)."""
        endif = self.i
        self.next()
        clause = self.else_clause()
        self.dangling[endif] = (self.i, clause)
        self.i = endif
        return clause

    def else_clause(self) -> ir.Block:
        """After `else`: `if ...` (an unscoped Block holding that If) or a body."""
        if self.at("if"):
            where = self.where(self.peek())
            lead = self.leading_trailing()
            stmt = self.if_statement()
            stmt.comment = lead
            return ir.Block([stmt], False, where=where)
        return self.body()

    def else_section(self) -> ir.Section:
        """`#ifdef M else ... [#else [else ...]] #endif`, then the rest of the chain, on both sides."""
        tok = self.next()
        name, macro = directive(tok)
        self.expect("else")
        body = [self.else_clause()]
        other: list = []
        if self.at_directive(frozenset({"else"})):
            self.next()
            if self.at("else"):
                self.next()
                other = [self.else_clause()]
        self.close_section(tok)
        section = ir.Section(macro, name == "ifdef", body, other, where=self.where(tok), else_branch=True)
        rest_tok = self.peek()
        rest = self.else_tail()
        if rest is not None:
            for side, value in ((section.body, rest), (section.other, copy.deepcopy(rest))):
                if not continue_chain(side, value):
                    raise self.error("an 'else' after the final 'else' of its 'if'", rest_tok)
        return section

    def simple(self, single: bool = False) -> list[ir.Stmt] | ir.Stmt:
        """A declaration (several for `T a, b;`), an assignment or an expression statement; with
        `single` (a for loop's parts) one statement."""
        tok = self.peek()
        where = self.where(tok)
        if self.declaration_ahead():
            decls = self.declaration()
            if single and len(decls) != 1:
                raise self.error("several declarations in a for loop", tok)
            return decls[0] if single else decls
        if tok.kind == "op" and tok.text in ("++", "--"):
            self.next()
            stmt = ir.Assign(tok.text, self.postfix(self.primary()), None, where=where)
        else:
            target = self.expression()
            op = self.peek()
            if op.kind == "op" and op.text in ASSIGN:
                self.next()
                value = self.expression()
                if op.text == "=" and self.at("="):  # `a = b = x`: `b = x; a = b;`
                    self.next()
                    stmts = [ir.Assign("=", value, self.expression(), where=where),
                             ir.Assign("=", target, copy.deepcopy(value), where=where)]
                    if self.peek().kind == "op" and self.peek().text in ASSIGN:
                        raise self.error("an assignment chain of more than two")
                    if single:
                        raise self.error("a chained assignment in a for loop", tok)
                    return stmts
                if self.peek().kind == "op" and self.peek().text in ASSIGN:
                    raise self.error("a chained compound assignment")
                stmt = ir.Assign(op.text, target, value, where=where)
            elif op.kind == "op" and op.text in ("++", "--"):
                self.next()
                stmt = ir.Assign(op.text, target, None, where=where)
            else:
                stmt = ir.ExprStatement(target, where=where)
        return stmt if single else [stmt]

    def declaration_ahead(self) -> bool:
        if self.at("const"):
            return True
        if self.peek().kind != "id":
            return False
        if self.peek(1).kind == "id":
            return True
        if self.at("[", 1):  # `float[3] x`
            k = 2
            while not self.at("]", k) and self.peek(k).kind != "eof":
                k += 1
            return self.peek(k + 1).kind == "id"
        return False

    def type_name(self) -> str:
        tok = self.identifier()
        return tok.text + (f"[{self.array_suffix()}]" if self.at("[") else "")

    def declaration(self) -> list[ir.Declare]:
        const = False
        if self.at("const"):
            self.next()
            const = True
        base = self.type_name()
        out = []
        while True:
            name = self.identifier()
            t = base + (f"[{self.array_suffix()}]" if self.at("[") else "")
            init = None
            if self.at("="):
                self.next()
                init = self.expression()
            out.append(ir.Declare(t, name.text, init, const, where=self.where(name)))
            if not self.at(","):
                return out
            self.next()

    # -- top level ---------------------------------------------------------------------------------
    def module(self) -> ir.Module:
        includes: list[str] = []
        features: list[tuple] = []
        items = self.item_list(lambda p: p.peek().kind == "eof", includes, features)
        if self.peek().kind != "eof":
            raise self.error(f"'{self.peek().text}' without an #ifdef")
        return ir.Module(self.path, items, includes, features)

    def item_list(self, closes, includes: list, features: list) -> list[ir.Item]:
        items: list = []
        pending: list[Token] = []
        while True:
            pending = self.item_comment(pending)
            if closes(self) or self.at_directive(SECTION_CLOSE):
                return items
            tok = self.peek()
            if tok.kind == "pp":
                name, rest = directive(tok)
                if name in SECTION_OPEN:
                    section = self.section(lambda stop: self.item_list(stop, includes, features))
                    items.append(section)
                    pending = []
                    continue
                self.next()
                item = self.directive_item(tok, name, rest, includes, features)
                if item is None:
                    continue
            else:
                item = self.item()
                if item is None:  # a prototype
                    pending = []
                    continue
            if pending:
                item.comment = [c.text for c in pending]
            pending = []
            items.append(item)

    def directive_item(self, tok: Token, name: str, rest: str, includes: list, features: list) -> ir.Item | None:
        if name == "include":
            m = re.match(INCLUDE, rest)
            if not m:
                raise self.error(f"malformed '{tok.text}'", tok)
            includes.append(os.path.normpath(os.path.join(os.path.dirname(self.path), m.group(1))))
            return None
        if name == "pragma":
            m = re.match(DECLARATION, tok.text)
            if not m:
                raise self.error(f"unknown pragma '{tok.text}'", tok)
            features.append(m.groups())
            return None
        if name == "define":
            m = re.match(DEFINE, rest)
            if not m or not m.group(2):
                raise self.error(f"'{tok.text}' defines no value", tok)
            offset = tok.text.index(m.group(2), tok.text.index(m.group(1)) + len(m.group(1)))
            value_tokens = tokenize(self.path, m.group(2), line=tok.line, column=tok.column + offset)
            sub = Parser(self.path, value_tokens)
            value = sub.expression()
            if sub.peek().kind != "eof":
                raise sub.error(f"unexpected '{sub.peek().text}' in a #define")
            return ir.Constant(None, m.group(1), value, where=self.where(tok))
        raise self.error(f"preprocessor line '{tok.text}' here", tok)

    def item(self) -> ir.Item | None:
        tok = self.peek()
        where = self.where(tok)
        if self.at("struct"):
            self.next()
            name = self.identifier().text
            self.expect("{")
            members = []
            while not self.at("}"):
                t = self.type_name()
                while True:
                    member = self.identifier().text
                    members.append((t + (f"[{self.array_suffix()}]" if self.at("[") else ""), member))
                    if not self.at(","):
                        break
                    self.next()
                self.expect(";")
            self.expect("}")
            self.expect(";")
            return ir.Struct(name, members, where=where)
        if self.at("uniform"):  # a uniform the source declares (OCIO's LUT textures: cms/ocio.py)
            self.next()
            decls = self.declaration()
            self.expect(";")
            if len(decls) != 1 or decls[0].init is not None:
                raise self.error("a uniform declaration is one name and no value", tok)
            return ir.Global(decls[0].type, decls[0].name, kind="uniform", where=decls[0].where)
        if self.at("const") or not self.at("(", 2):
            decls = self.declaration()
            self.expect(";")
            if len(decls) != 1:
                raise self.error("several globals in one declaration", tok)
            d = decls[0]
            if d.const:
                if d.init is None:
                    raise self.error(f"constant '{d.name}' has no value", tok)
                return ir.Constant(d.type, d.name, d.init, where=d.where)
            return ir.Global(d.type, d.name, where=d.where, init=d.init)
        returns = self.type_name()
        name = self.identifier()
        self.expect("(")
        params = []
        if self.at("void") and self.at(")", 1):
            self.next()
        while not self.at(")"):
            ptok = self.peek()
            qualifier, const = "in", False
            while self.peek().kind == "id" and self.peek().text in QUALIFIERS:
                word = self.next().text
                if word == "const":
                    const = True
                else:
                    qualifier = word
            t = self.type_name()
            pname = self.identifier().text
            if self.at("["):
                t += f"[{self.array_suffix()}]"
            params.append(ir.Param(qualifier, t, pname, const, where=self.where(ptok)))
            if not self.at(")"):
                self.expect(",")
        self.expect(")")
        if self.at(";"):
            self.next()
            return None
        return ir.Function(returns, name.text, params, self.block(), where=where)


def continue_chain(side: list, rest: ir.Block) -> bool:
    """`rest` as the else of the last `if` of the else clause `side` holds (an empty side: `rest`
    is the clause); False where that chain already ends in an else."""
    if not side:
        side.append(rest)
        return True
    clause = side[0]
    if clause.scoped or len(clause.body) != 1:
        return False
    node = clause.body[0]
    if isinstance(node, ir.Section):  # a nested else section: both its sides continue
        return continue_chain(node.body, rest) and continue_chain(node.other, copy.deepcopy(rest))
    if not isinstance(node, ir.If):
        return False
    while node.other is not None:
        inner = node.other
        if inner.scoped or len(inner.body) != 1 or not isinstance(inner.body[0], (ir.If, ir.Section)):
            return False
        if isinstance(inner.body[0], ir.Section):
            return continue_chain([inner], rest)
        node = inner.body[0]
    node.other = rest
    return True


def number(tok: Token, where) -> ir.Literal:
    text = tok.text
    lower = text.lower()
    if lower.startswith("0x"):
        value = int(lower.rstrip("u"), 16)
    else:
        body = lower.rstrip("fu")
        if any(c in body for c in ".e"):
            if lower.endswith("u"):
                raise source_error(where[0], where[1], where[2], f"'{text}': a float with an unsigned suffix")
            return ir.Literal(float(body), text, where=where)
        if lower.endswith("f"):
            raise source_error(where[0], where[1], where[2], f"'{text}': an integer with a float suffix")
        value = int(body)
    if value >= 2 ** 32:
        raise source_error(where[0], where[1], where[2], f"'{text}' does not fit in 32 bits")
    return ir.Literal(value, text, where=where)
