# What the plotting tools share: a CSV read with its required columns checked, and bad input
# reported on one line naming the tool and the file, exit code 2 (as the ispm CLI does).
import csv
import os
import sys

EXIT_BAD_INPUT = 2  # the same code the ispm CLI uses for bad input


def fail(message):
    print(f"{os.path.basename(sys.argv[0])}: {message}", file=sys.stderr)
    sys.exit(EXIT_BAD_INPUT)


def read_rows(path, required_columns, what):
    """The rows of CSV `path` as dicts; fails naming the missing columns and `what` it should be."""
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            missing = [c for c in required_columns if c not in (reader.fieldnames or [])]
            if missing:
                fail(f"{path}: expected columns {', '.join(missing)} ({what})")
            return list(reader)
    except OSError as e:
        fail(f"{path}: {e.strerror}")
