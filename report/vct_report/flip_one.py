"""flip_one.py PT.exr VCT.exr OUT.png: mean HDR-FLIP of VCT against PT on stdout, map to OUT.png.
Runs as its own process because flip-evaluator's C++ core calls exit() on some inputs (a constant
reference: "start exposure must be smaller than stop exposure")."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from vct_report import runio  # noqa: E402


def main(ref_path, test_path, out_png):
    import flip_evaluator
    a, b = runio.read_exr(ref_path), runio.read_exr(test_path)
    if a is None or b is None or a.shape != b.shape:
        return 1
    a = np.clip(np.nan_to_num(a[:, :, :3]), 0, None)
    b = np.clip(np.nan_to_num(b[:, :, :3]), 0, None)
    if a.max() <= 0 and b.max() <= 0:
        print(0.0)
        return 0
    emap, mean, _ = flip_evaluator.evaluate(a, b, "HDR")
    runio.write_png(out_png, np.asarray(emap, dtype=np.float32))
    print(float(mean))
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
