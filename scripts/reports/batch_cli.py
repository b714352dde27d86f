"""The command line every Monte Carlo benchmark of scripts/reports shares (clutter.py,
pedestrians.py): simulator, folders, variants, jobs, a subset of classes and laws."""
import argparse
import os
import sys


def parse(doc, tool, out_name, root, classes, laws, quick_runs, extra=None):
    """The parsed arguments, with args.classes and args.laws as lists checked against `classes`
    and `laws` (an unknown name exits naming the known ones) and args.runs set by --quick.
    `extra(parser)` adds a benchmark's own options."""
    parser = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sim", required=True)
    parser.add_argument("--out", default=os.path.join(root, "out", out_name))
    parser.add_argument("--docs", default=os.path.join(root, "docs"))
    parser.add_argument("--runs", type=int, default=50)
    parser.add_argument("--jobs", type=int, default=None, help="runs at once (default: every core)")
    parser.add_argument("--classes", default="", help="comma-separated subset of the classes")
    parser.add_argument("--laws", default="", help="comma-separated subset of the laws")
    parser.add_argument("--quick", action="store_true", help=f"{quick_runs} variants per class and law")
    if extra:
        extra(parser)
    args = parser.parse_args()
    args.classes = [c for c in args.classes.split(",") if c]
    args.laws = [law for law in args.laws.split(",") if law]
    unknown = [c for c in args.classes if c not in classes] + [law for law in args.laws if law not in laws]
    if unknown:
        sys.exit(f"{tool}: unknown class or law {', '.join(unknown)}; classes: {', '.join(classes)}; "
                 f"laws: {', '.join(laws)}")
    if args.quick:
        args.runs = quick_runs
    for name in ("sim", "out", "docs"):
        setattr(args, name, os.path.abspath(getattr(args, name)))
    return args
