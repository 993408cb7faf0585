#!/usr/bin/env python3
"""Proves from a firmware image's machine code that the control cycle reaches
no soft float, no f64 and no panic.

    check-cycle-image.py IMAGE.elf ROOT [ROOT...]

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
    image, roots = sys.argv[1], sys.argv[2:]
    dis = subprocess.run(["arm-none-eabi-objdump", "-d", "--no-show-raw-insn", image], capture_output=True, text=True, check=True).stdout
    calls, indirect, start, size = {}, {}, {}, {}
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

    root_names = [f for f in calls if any(r in f for r in roots)]
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
    for f in sorted(seen):
        for pattern, what in FORBIDDEN:
            if pattern.search(f):
                problems.append(f"{what}: {path(f)}")
        for call in indirect.get(f, ()):
            problems.append(f"indirect call `{call}` in {path(f)}")
    print(f"{image}: {len(seen)} functions reachable from {len(root_names)} cycle entr{'y' if len(root_names) == 1 else 'ies'}:")
    for f in sorted(seen, key=lambda x: -size.get(x, 0)):
        print(f"  {size.get(f, 0):6d} B  {names.get(f, f)}")
    if problems:
        print("FAIL: the cycle reaches", file=sys.stderr)
        for p in problems:
            print(f"  {p}", file=sys.stderr)
        return 1
    print("ok: no soft float, no f64, no panic, no indirect call reachable from the cycle")
    return 0


if __name__ == "__main__":
    sys.exit(main())
