#!/usr/bin/env python3
"""Whole-range stereo confidence on a Middlebury pair, from numpy arrays.

Reads the pair and its ground truth with matplotlib (numpy arrays, no OpenCV in Python), computes the BTSAD cost
volume, the winner-take-all disparity, Merrell's confidence model fitted by maximum likelihood without ground truth
(thesis 4.3.2), and scores it against the ground truth (bad-pixel rate, ROC AUC, C(d in GT) at bad pixels, thesis
4.3.4). The images cross into C++ without copies; --out draws disparity and confidence.

    PYTHONPATH=build/python python3 examples/python/stereo_confidence.py --pair /work/shared/data/middlebury/tsukuba
"""

import argparse
import os
import sys

import numpy as np

import cairn.perception as perception

SCALES = {"tsukuba": 16}  # ground-truth PNG value per pixel of disparity; 8 for the other 2001 pairs


def read_gray(path):
    """A PNG as uint8 grey (matplotlib reads PNGs as floats in [0, 1])."""
    import matplotlib.image

    image = matplotlib.image.imread(path)
    if image.ndim == 3:
        image = image[..., :3] @ np.array([0.299, 0.587, 0.114])
    return np.round(image * 255.0).astype(np.uint8)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pair", required=True, help="a Middlebury folder (im2.png, im6.png, disp2.png)")
    parser.add_argument("--max-disparity", type=int, default=None, help="default: from the ground truth")
    parser.add_argument("--out", help="write disparity and confidence images to this PNG")
    args = parser.parse_args()

    name = os.path.basename(os.path.normpath(args.pair))
    scale = SCALES.get(name, 8)
    left = read_gray(os.path.join(args.pair, "im2.png"))
    right = read_gray(os.path.join(args.pair, "im6.png"))
    truth = read_gray(os.path.join(args.pair, "disp2.png")).astype(np.float32) / scale

    options = perception.CostVolumeOptions()
    options.max_disparity = args.max_disparity or int(np.ceil(truth.max()))
    costs, wta = perception.ComputeCostVolumeAndWinnerTakeAll(left, right, options, perception.WtaOptions())
    samples = perception.CollectConsistentWtaCosts(costs, wta)
    model = perception.ConfidenceModel.FitMaximumLikelihood(perception.ConfidenceModelType.kMerrell, options.cost,
                                                            list(samples))
    confidence = perception.ComputeConfidence(costs, model)
    evaluation = perception.EvaluateStereo(confidence, wta, truth)
    print(f"{name}: {left.shape[1]}x{left.shape[0]}, disparities 0..{options.max_disparity}, model {model.Describe()}")
    print(f"bad pixels {100 * evaluation.bad_pixel_rate:.1f}% (sub-pixel {100 * evaluation.bad_pixel_rate_subpixel:.1f}%),"
          f" AUC {evaluation.auc:.4f} (optimal {evaluation.auc_optimal:.4f}), C(d in GT) at bad pixels "
          f"{evaluation.c_gt_badpx:.3f}, {evaluation.num_pixels} pixels")

    if args.out:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        volume = confidence.array()  # (H, W, D) view of the C++ volume, no copy
        peak = np.take_along_axis(volume, np.clip(wta.best_index, 0, None)[..., None].astype(np.intp), 2)[..., 0]
        figure, axes = plt.subplots(1, 3, figsize=(12, 3.6))
        axes[0].imshow(left, cmap="gray")
        axes[0].set_title("left image")
        axes[1].imshow(wta.disparity, cmap="viridis", vmin=0, vmax=options.max_disparity)
        axes[1].set_title("WTA disparity")
        axes[2].imshow(peak, cmap="magma", vmin=0, vmax=1)
        axes[2].set_title("confidence C(d) of the WTA disparity")
        for a in axes:
            a.axis("off")
        figure.tight_layout()
        figure.savefig(args.out, dpi=100)
        print(f"wrote {args.out}")
    return 0 if evaluation.auc < evaluation.bad_pixel_rate else 1


if __name__ == "__main__":
    sys.exit(main())
