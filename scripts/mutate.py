"""Mutation testing: change one token of the physics and see whether a test fails.

    .venv/bin/python scripts/mutate.py src/ballscrew/rolling_losses.py \
        src/ballscrew/friction/complete.py --tests tests/friction/test_complete.py

For every numeric constant (scaled by 1.1, or 0 <-> 1 for the whole numbers 0 and 1), every
arithmetic operator (+ <-> -, * <-> /, ** -> *) and every comparison (< <-> <=, > <-> >=)
outside docstrings, the script writes the mutated module, runs the given tests (default: the
whole suite) with ``-x -q``, and records whether they failed (the mutant is killed) or passed
(it survived). The file is restored after every mutant, also on Ctrl-C. Survivors are
printed with their line: each is a test still to write, or an equivalent mutant to list.
Not part of the CI run (it takes minutes per module).
"""

from __future__ import annotations

import argparse
import ast
import signal
import subprocess
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

SWAP_BINOP: dict[type[ast.operator], type[ast.operator]] = {
    ast.Add: ast.Sub,
    ast.Sub: ast.Add,
    ast.Mult: ast.Div,
    ast.Div: ast.Mult,
    ast.Pow: ast.Mult,
}
SWAP_CMP: dict[type[ast.cmpop], type[ast.cmpop]] = {
    ast.Lt: ast.LtE,
    ast.LtE: ast.Lt,
    ast.Gt: ast.GtE,
    ast.GtE: ast.Gt,
}


@dataclass(frozen=True)
class Mutant:
    """One mutation: the n-th candidate node of its kind, with a description."""

    index: int
    line: int
    text: str
    column: int = 0


def _docstring_ids(tree: ast.AST) -> set[int]:
    ids = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Module | ast.FunctionDef | ast.ClassDef | ast.AsyncFunctionDef):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                ids.add(id(body[0].value))
    return ids


def _candidates(tree: ast.AST) -> list[ast.AST]:
    skip = _docstring_ids(tree)
    out: list[ast.AST] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and id(node) not in skip:
            if isinstance(node.value, bool) or not isinstance(node.value, int | float):
                continue
            out.append(node)
        elif isinstance(node, ast.BinOp) and type(node.op) in SWAP_BINOP:
            out.append(node)
        elif isinstance(node, ast.Compare) and type(node.ops[0]) in SWAP_CMP:
            out.append(node)
    return out


def _apply(node: ast.AST) -> str:
    if isinstance(node, ast.Constant):
        old = node.value
        new = {0: 1, 1: 0}.get(old, old * 1.1) if isinstance(old, int) else old * 1.1
        node.value = new if old not in (0.0, 1.0) or isinstance(old, int) else 1.0 - old
        return f"{old!r} -> {node.value!r}"
    if isinstance(node, ast.BinOp):
        old_op = type(node.op)
        node.op = SWAP_BINOP[old_op]()
        return f"{old_op.__name__} -> {type(node.op).__name__}"
    assert isinstance(node, ast.Compare)
    old_cmp = type(node.ops[0])
    node.ops[0] = SWAP_CMP[old_cmp]()
    return f"{old_cmp.__name__} -> {type(node.ops[0]).__name__}"


def mutants(source: str) -> list[Mutant]:
    """Every mutation of ``source`` this script makes, in order."""
    tree = ast.parse(source)
    return [
        Mutant(i, getattr(node, "lineno", 0), _apply(node), getattr(node, "col_offset", -1) + 1)
        for i, node in enumerate(_candidates(tree))
    ]


def mutated(source: str, index: int) -> str:
    """``source`` with mutation ``index`` applied (reformatted by ast.unparse)."""
    tree = ast.parse(source)
    _apply(_candidates(tree)[index])
    return ast.unparse(tree)


def _address_space_cap(gib: float) -> Callable[[], None]:
    """A child's preparation that caps its address space at ``gib`` GiB (RLIMIT_AS)."""

    def cap() -> None:
        import resource

        limit = int(gib * 2**30)
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

    return cap


def main() -> None:
    """Run the mutants of each file and report the survivors."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("files", nargs="+", type=Path)
    parser.add_argument("--tests", nargs="*", default=["tests", "src"], help="pytest targets")
    parser.add_argument("--limit", type=int, default=0, help="at most this many per file")
    parser.add_argument(
        "--lines", default="",
        help="only the mutants on these lines, e.g. '12,40,41' (to rerun the survivors of an "
        "earlier run after writing tests)",
    )  # fmt: skip
    parser.add_argument(
        "--memory", type=float, default=4.0,
        help="GiB of address space per mutant's test run; a run that grows past it (a mutant "
        "that makes a loop endless and fills a list) fails, and counts as killed",
    )  # fmt: skip
    parser.add_argument(
        "--timeout", type=float, default=300.0,
        help="seconds per mutant's test run; a run that hangs (a mutant that makes a loop "
        "endless) counts as killed",
    )  # fmt: skip
    args = parser.parse_args()
    # SIGTERM unwinds like Ctrl-C, so the finally below restores the file being mutated.
    signal.signal(signal.SIGTERM, signal.default_int_handler)
    python = sys.executable
    totals = {"killed": 0, "survived": 0}
    for path in args.files:
        original = path.read_text("utf-8")
        todo = mutants(original)
        if args.lines:
            wanted = {int(x) for x in args.lines.split(",") if x.strip()}
            todo = [m for m in todo if m.line in wanted]
        if args.limit:
            todo = todo[: args.limit]
        survivors = []
        start = time.monotonic()
        try:
            for k, m in enumerate(todo, 1):
                path.write_text(mutated(original, m.index), "utf-8")
                try:
                    run = subprocess.run(
                        [python, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider",
                         *args.tests],
                        capture_output=True,
                        text=True,
                        check=False,
                        timeout=args.timeout,
                        preexec_fn=_address_space_cap(args.memory),
                    )  # fmt: skip
                    killed = run.returncode != 0
                except subprocess.TimeoutExpired:
                    killed = True
                totals["killed" if killed else "survived"] += 1
                if not killed:
                    survivors.append(m)
                print(
                    f"\r{path}: {k}/{len(todo)} mutants, {len(survivors)} survived",
                    end="",
                    file=sys.stderr,
                )
        finally:
            path.write_text(original, "utf-8")
        print(file=sys.stderr)
        print(f"{path}: {len(todo)} mutants, {len(todo) - len(survivors)} killed, "
              f"{len(survivors)} survived ({time.monotonic() - start:.0f} s)")  # fmt: skip
        for m in survivors:
            print(f"  survived: line {m.line}, column {m.column}: {m.text}")
    print(f"total: {totals['killed']} killed, {totals['survived']} survived")


if __name__ == "__main__":
    main()
