#!/usr/bin/env python3
"""Instruction, block and branch counts of SPIR-V modules: what a GPU pays for in code size and
divergence, measured on the binary itself (SPIR-V 1.6 specification, section 2.3 "Physical Layout of a
SPIR-V Module and Instruction": a 5-word header, then instructions whose first word holds the word count
in its high 16 bits and the opcode in its low 16).

    python3 bench/spirv_stats.py [--baseline REV] [--peer NAME=PATH.spv ...] [--out bench/SPIRV_STATS.md]

Counts every module in assets/spirv/ (aokit's committed SPIR-V) and any peer modules given, and
writes Markdown tables; with --baseline, also each module's counts at git revision REV beside
today's (before → after). Standard library only.
"""

import argparse
import hashlib
import os
import struct
import subprocess
import sys

# Opcodes (SPIR-V 1.6 specification, section 3.52 "Instructions").
OP = {
    "OpFunction": 54,
    "OpFunctionCall": 57,
    "OpLoad": 61,
    "OpStore": 62,
    "OpAccessChain": 65,
    "OpInBoundsAccessChain": 66,
    "OpImageSampleExplicitLod": 88,
    "OpImageFetch": 95,
    "OpImageGather": 96,
    "OpImageRead": 98,
    "OpImageWrite": 99,
    "OpConvertFToU": 109,
    "OpConvertFToS": 110,
    "OpConvertUToF": 112,
    "OpUDiv": 134,
    "OpSDiv": 135,
    "OpFDiv": 136,
    "OpUMod": 137,
    "OpSRem": 138,
    "OpSMod": 139,
    "OpFRem": 140,
    "OpFMod": 141,
    "OpSelect": 169,
    "OpULessThan": 176,
    "OpPhi": 245,
    "OpLoopMerge": 246,
    "OpLabel": 248,
    "OpBranchConditional": 250,
    "OpSwitch": 251,
    "OpKill": 252,
    "OpReturn": 253,
}
# Debug instructions (OpSource..OpModuleProcessed, OpLine, OpNoLine) say nothing about the code.
DEBUG = set(range(2, 9)) | {317, 330}
MAGIC = 0x07230203


def stats(data: bytes) -> dict:
    """Counts of one module's binary `data`; raises ValueError on a malformed module."""
    if len(data) < 20 or len(data) % 4:
        raise ValueError(f"{len(data)} bytes: not a SPIR-V module")
    endian = "<" if struct.unpack_from("<I", data)[0] == MAGIC else ">"
    words = struct.unpack(f"{endian}{len(data) // 4}I", data)
    if words[0] != MAGIC:
        raise ValueError("no SPIR-V magic number")
    counts = {name: 0 for name in OP}
    by_code = {code: name for name, code in OP.items()}
    instructions = 0
    i = 5
    while i < len(words):
        count, opcode = words[i] >> 16, words[i] & 0xFFFF
        if count == 0 or i + count > len(words):
            raise ValueError(f"instruction at word {i}: word count {count}")
        if opcode not in DEBUG:
            instructions += 1
        name = by_code.get(opcode)
        if name:
            counts[name] += 1
        i += count
    divisions = sum(counts[k] for k in ("OpUDiv", "OpSDiv", "OpFDiv", "OpUMod", "OpSRem", "OpSMod", "OpFRem", "OpFMod"))
    image = sum(counts[k] for k in ("OpImageSampleExplicitLod", "OpImageFetch", "OpImageGather", "OpImageRead", "OpImageWrite"))
    return {
        "instructions": instructions,
        "functions": counts["OpFunction"],
        "blocks": counts["OpLabel"],
        "conditional branches": counts["OpBranchConditional"],
        "switches": counts["OpSwitch"],
        "loops": counts["OpLoopMerge"],
        "OpSelect": counts["OpSelect"],
        "OpULessThan": counts["OpULessThan"],
        "divisions": divisions,
        "float→int": counts["OpConvertFToU"] + counts["OpConvertFToS"],
        "uint→float": counts["OpConvertUToF"],
        "loads": counts["OpLoad"],
        "access chains": counts["OpAccessChain"] + counts["OpInBoundsAccessChain"],
        "image ops": image,
        "calls": counts["OpFunctionCall"],
    }


COLUMNS = [
    "instructions",
    "blocks",
    "conditional branches",
    "switches",
    "loops",
    "OpSelect",
    "OpULessThan",
    "divisions",
    "float→int",
    "uint→float",
    "loads",
    "access chains",
    "image ops",
    "calls",
]


def table(rows) -> str:
    head = "| module | " + " | ".join(COLUMNS) + " |\n|---|" + "---:|" * len(COLUMNS) + "\n"
    return head + "".join(f"| {name} | " + " | ".join(str(s[c]) for c in COLUMNS) + " |\n" for name, s in rows)


BEFORE_AFTER = ["instructions", "blocks", "conditional branches", "OpULessThan", "OpSelect", "float→int"]


def baseline_table(repo: str, rev: str, rows) -> str:
    """Before (the modules at git revision `rev`) → after (today's) for the columns above."""
    def at_rev(name):
        path = f"assets/spirv/{name}"
        done = subprocess.run(["git", "-C", repo, "show", f"{rev}:{path}"], capture_output=True)
        return stats(done.stdout) if done.returncode == 0 else None
    out = f"\n## Before ({rev}) → after\n\n| module | " + " | ".join(BEFORE_AFTER) + " |\n|---|" + "---:|" * len(BEFORE_AFTER) + "\n"
    for name, now in rows:
        before = at_rev(name)
        cells = [f"{before[c]} → {now[c]}" if before else f"new: {now[c]}" for c in BEFORE_AFTER]
        out += f"| {name} | " + " | ".join(cells) + " |\n"
    return out


def main() -> int:
    here = os.path.dirname(os.path.abspath(__file__))
    repo = os.path.dirname(here)
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--spirv", default=os.path.join(repo, "assets", "spirv"), help="folder of aokit's modules")
    parser.add_argument("--peer", action="append", default=[], metavar="NAME=PATH", help="a peer module to count beside aokit's")
    parser.add_argument("--baseline", metavar="REV", help="a git revision whose assets/spirv/ to compare with")
    parser.add_argument("--out", default=os.path.join(here, "SPIRV_STATS.md"), help="the Markdown file to write ('-': stdout)")
    args = parser.parse_args()
    rows = []
    digest = hashlib.sha256()
    for name in sorted(os.listdir(args.spirv)):
        if name.endswith(".spv"):
            data = open(os.path.join(args.spirv, name), "rb").read()
            digest.update(name.encode() + data)
            try:
                rows.append((name, stats(data)))
            except ValueError as e:
                print(f"spirv_stats: {name}: {e}", file=sys.stderr)
                return 1
    if not rows:
        print(f"spirv_stats: no .spv modules in {args.spirv}", file=sys.stderr)
        return 1
    peers = []
    for spec in args.peer:
        name, sep, path = spec.partition("=")
        if not sep or not path:
            print(f"spirv_stats: --peer {spec!r}: expected NAME=PATH.spv", file=sys.stderr)
            return 2
        try:
            peers.append((name, stats(open(path, "rb").read())))
        except (OSError, ValueError) as e:
            print(f"spirv_stats: --peer {name}: {e}", file=sys.stderr)
            return 1
    text = (
        "# SPIR-V module statistics\n\n"
        "Generated by `python3 bench/spirv_stats.py` from the committed modules in `assets/spirv/` "
        f"(sha256 of names and bytes `{digest.hexdigest()[:16]}`). Counts of the binary's "
        "instructions (debug instructions left out), blocks (`OpLabel`), conditional branches "
        "(`OpBranchConditional`), switches, loops (`OpLoopMerge`), `OpSelect`, `OpULessThan` "
        "(index bounds checks compile to it), divisions and remainders, float-to-integer and unsigned-to-float conversions (lavapipe compiles each float-to-integer conversion to eight scalar saturating ones per vector, an unsigned-to-float one to several instructions), loads, access chains, "
        "image instructions and function calls: what a GPU pays for in code size and divergence "
        "(issue 26). A module holds one entry point and the functions it calls.\n\n"
        "## aokit\n\n" + table(rows)
    )
    if args.baseline:
        text += baseline_table(repo, args.baseline, rows)
    if peers:
        text += "\n## Peers\n\n" + table(peers)
    if args.out == "-":
        sys.stdout.write(text)
    else:
        with open(args.out, "w") as f:
            f.write(text)
        print(f"wrote {args.out} ({len(rows)} modules, {len(peers)} peers)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
