#!/usr/bin/env python3
"""Proves from a firmware image's machine code that the control cycle reaches
no soft float, no f64 and no panic.

    check-cycle-image.py IMAGE.elf ROOT [ROOT...]
    check-cycle-image.py --stack-only IMAGE.elf ROOT [ROOT...]

ROOT is either an exact symbol or a substring (5 characters or more) of
mangled names. With --stack-only it only prints the static stack bound below
the roots (the deepest chain of prologue frames: push, vpush, sub sp).

ROOT is a substring of the mangled name of a cycle entry (the limiter's
`cycle` and `step_frame` are `#[inline(never)]` so they exist in every
image). The script disassembles IMAGE with arm-none-eabi-objdump, builds the
call graph from every direct branch (bl, blx <label>, b/b.w and conditional
branches, cbz/cbnz to another function: tail calls included), walks it from
the roots and fails if it reaches:
  - a soft-float routine: __aeabi_d*, __aeabi_f*, __aeabi_[ilu]*2d, any
    __*df*/__*sf* helper (the M4F does f32 in hardware; anything named so
    is a software float routine, f64 ones included);
  - a panic: anything in core::panicking, core::result::unwrap_failed,
    core::option::expect_failed, slice index failures, rust_begin_unwind;
  - an indirect call (blx/bx through a register other than lr), which the
    walk cannot follow and so cannot prove anything about.
It also prints the static stack bound of the cycle: the deepest chain of
prologue frames (push, stmdb sp!, vpush, sub sp, #N) below the roots; a
register-sized `sub sp` or recursion fails the check (no bound).
Exit 0 when the walk is clean (and prints the reachable functions with their
sizes), 1 otherwise, 2 on usage errors.
"""
import re
import subprocess
import sys

FORBIDDEN = [
    (re.compile(r"__aeabi_(d|f)[a-z0-9]*|__aeabi_[ilu]+2[df]"), "soft float"),
    (re.compile(r"^__\w*(df|sf)\d\b|^__\w*(df|sf)\d$"), "soft float"),
    (re.compile(r"panicking|unwrap_failed|expect_failed|slice_index|slice_start_index|slice_end_index|rust_begin_unwind|panic_bounds_check|panic_fmt|panic_const"), "panic"),
]
FUNC = re.compile(r"^([0-9a-f]+) <(.+)>:$")
INSN = re.compile(r"^\s+([0-9a-f]+):\s+(?:[0-9a-f]{4}\s?)+\s+([a-z][a-z0-9.]*)\s*(.*)$")
TARGET = re.compile(r"<([^>+]+)(?:\+0x[0-9a-f]+)?>")
BRANCH = re.compile(r"^(bl|blx|b|cbz|cbnz)(eq|ne|cs|cc|hs|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le|al)?(\.[nw])?$")


def stack_bytes(op, args, func, dynamic):
    """Bytes an instruction moves the stack pointer down by (prologue: push,
    stmdb sp!, vpush, sub sp); a register-sized `sub sp` is dynamic."""
    regs = re.search(r"\{([^}]*)\}", args)
    if op.startswith("push") or (op.startswith("stmdb") and args.startswith("sp!")):
        return 4 * len([r for r in regs.group(1).split(",") if r.strip()]) if regs else 0
    if op.startswith("vpush") and regs:
        n = 0
        for r in regs.group(1).split(","):
            r = r.strip()
            span = re.match(r"([sd])(\d+)-[sd](\d+)", r)
            if span:
                n += (int(span.group(3)) - int(span.group(2)) + 1) * (8 if span.group(1) == "d" else 4)
            elif r:
                n += 8 if r.startswith("d") else 4
        return n
    m = re.match(r"sp, (?:sp, )?#(\d+)", args)
    if op.startswith("sub") and m:
        return int(m.group(1))
    if op.startswith("sub") and re.match(r"sp, (?:sp, )?r", args):
        dynamic.add(func)
    return 0


def worst_stack(roots, calls, frame):
    """Deepest stack (bytes) of a call chain from `roots`, the chain, and the
    functions where a chain came back to itself (recursion: each such loop is
    counted once, so the bound holds only if it cannot repeat)."""
    memo, on_path, loops = {}, set(), set()

    def depth(f):
        if f in memo:
            return memo[f]
        if f in on_path:
            loops.add(f)
            return (0, [])
        on_path.add(f)
        best = (0, [])
        for g in calls.get(f, ()):
            d = depth(g)
            if d[0] > best[0]:
                best = d
        on_path.discard(f)
        memo[f] = (frame.get(f, 0) + best[0], [f] + best[1])
        return memo[f]

    bound, chain = max((depth(r) for r in roots), key=lambda d: d[0])
    return bound, chain, loops


def short(name):
    """`a::b::C<T>::f::h123` -> `C<T>::f`: enough to read a chain."""
    parts = re.sub(r"::h[0-9a-f]{16}$", "", name).split("::")
    return "::".join(parts[-2:])


def demangle(names):
    try:
        out = subprocess.run(["arm-none-eabi-c++filt"], input="\n".join(names), capture_output=True, text=True, check=True).stdout
        return dict(zip(names, out.splitlines()))
    except (OSError, subprocess.CalledProcessError):
        return {n: n for n in names}


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    stack_only = "--stack-only" in sys.argv
    args = [a for a in sys.argv[1:] if a != "--stack-only"]
    image, roots = args[0], args[1:]
    dis = subprocess.run(["arm-none-eabi-objdump", "-d", "--no-show-raw-insn", image], capture_output=True, text=True, check=True).stdout
    calls, indirect, start, size, frame, dynamic = {}, {}, {}, {}, {}, set()
    current = None
    last_addr = 0
    for line in dis.splitlines():
        m = FUNC.match(line)
        if m:
            if current is not None:
                size[current] = last_addr - start[current] + 2
            current = m.group(2)
            start[current] = int(m.group(1), 16)
            last_addr = start[current]
            calls.setdefault(current, set())
            continue
        if current is None:
            continue
        m = re.match(r"^\s+([0-9a-f]+):\s+([a-z][a-z0-9.]*)\s*(.*)$", line)
        if not m:
            continue
        last_addr = int(m.group(1), 16)
        op, args = m.group(2), m.group(3)
        frame[current] = frame.get(current, 0) + stack_bytes(op, args, current, dynamic)
        if BRANCH.match(op):
            t = TARGET.search(args)
            if t and t.group(1) != current:
                calls[current].add(t.group(1))
            elif not t and op.startswith("bl"):
                indirect.setdefault(current, []).append(f"{op} {args}".strip())
        elif op.startswith("bx") or op.startswith("blx"):
            reg = args.split()[0] if args else ""
            if reg != "lr":
                indirect.setdefault(current, []).append(f"{op} {args}".strip())
    if current is not None:
        size[current] = last_addr - start[current] + 2

    root_names = [f for f in calls if any(r == f or (len(r) > 4 and r in f) for r in roots)]
    if not root_names:
        print(f"check-cycle-image: no function matching {roots} in {image}", file=sys.stderr)
        return 1
    seen, stack = set(), list(root_names)
    parent = {}
    while stack:
        f = stack.pop()
        if f in seen:
            continue
        seen.add(f)
        for g in calls.get(f, ()):
            if g not in seen:
                parent.setdefault(g, f)
                stack.append(g)
    names = demangle(sorted(seen))

    def path(f):
        chain = [f]
        while chain[-1] in parent and len(chain) < 30:
            chain.append(parent[chain[-1]])
        return " <- ".join(names.get(x, x) for x in chain)

    problems = []
    for f in sorted(seen & dynamic):
        problems.append(f"dynamic stack allocation in {path(f)}")
    for f in sorted(seen):
        for pattern, what in FORBIDDEN:
            if pattern.search(f):
                problems.append(f"{what}: {path(f)}")
        for call in indirect.get(f, ()):
            problems.append(f"indirect call `{call}` in {path(f)}")
    if stack_only:
        bound, chain, loops = worst_stack(root_names, calls, frame)
        print(f"static stack bound from {', '.join(short(names.get(r, r)) for r in root_names)}: {bound} bytes "
              f"(deepest chain: {' -> '.join(short(names.get(f, f)) for f in chain)}); "
              f"recursion counted once at: {', '.join(short(names.get(f, f)) for f in loops) or 'none'}; "
              f"{len(seen & set(indirect))} functions with indirect calls not followed")
        return 0
    print(f"{image}: {len(seen)} functions reachable from {len(root_names)} cycle entr{'y' if len(root_names) == 1 else 'ies'}:")
    for f in sorted(seen, key=lambda x: -size.get(x, 0)):
        print(f"  {size.get(f, 0):6d} B  {names.get(f, f)}")
    bound, chain, loops = worst_stack(root_names, calls, frame)
    if loops:
        problems.append(f"recursion below the cycle at {', '.join(names.get(f, f) for f in loops)}: no static stack bound")
    print(f"static stack bound of the cycle: {bound} bytes (deepest chain: {' -> '.join(short(names.get(f, f)) for f in chain)})")
    if problems:
        print("FAIL: the cycle reaches", file=sys.stderr)
        for p in problems:
            print(f"  {p}", file=sys.stderr)
        return 1
    print("ok: no soft float, no f64, no panic, no indirect call reachable from the cycle")
    return 0


if __name__ == "__main__":
    sys.exit(main())
