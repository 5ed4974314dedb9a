"""The command line the analyses share: which split of which data folder, and which of the model's rows."""

import argparse


def split_args(parse: bool = False) -> argparse.ArgumentParser:
    """--split and --data-dir (the folder `dynclevr run --data-dir` wrote); with `parse`, --parse as well."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--split", default="full-val")
    ap.add_argument("--data-dir", default="data")
    if parse:
        ap.add_argument("--parse", default="parsed", help="the estimate's directory (parsed, parsed-particle, ...)")
    return ap
