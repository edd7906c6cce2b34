"""Shared by the plotting scripts: a PNG is written under a temporary name
and renamed when complete, so that an interrupted run never leaves a
half-written picture (as the program does for its own files)."""
import os


def save_atomically(fig, path, **options):
    temporary = path[:-len(".png")] + ".tmp.png"
    fig.savefig(temporary, **options)
    os.replace(temporary, path)
