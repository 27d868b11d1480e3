"""Run sluice scenes and read their output files.

run() calls the sluice command with overrides and returns its summary as a
dict; Output reads an output file (fields, times, scalars, mesh) with h5py;
read_scalars_csv() reads OUT_scalars.csv without h5py. docs/output.md
describes the files.
"""
from .run import SluiceError, find_binary, run
from .output import Output, read_scalars_csv

__all__ = ["run", "find_binary", "SluiceError", "Output", "read_scalars_csv"]
__version__ = "0.1.0"
