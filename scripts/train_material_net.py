#!/usr/bin/python3
"""Trains a tiny fully-convolutional material segmentation network and exports it to ONNX for Cairn.

The training data are Cairn's own rendered material scenes:

    cairn friction-dataset --out /tmp/materials --images 240 --seed 1
    scripts/train_material_net.py --data /tmp/materials --out data/models/tiny_material_net

writes tiny_material_net.onnx and tiny_material_net.yaml (the label map and preprocessing that
cairn::perception::OnnxMaterialSegmenter reads). The network outputs per-label scores at a quarter of the input
resolution; the C++ side applies the softmax and resizes to the image.

Needs Debian's python3-torch, python3-onnx and python3-pil (no PyPI). Deterministic for a given --seed on one
machine (torch.use_deterministic_algorithms, a fixed thread count).
"""

import argparse
import glob
import os
import sys

import numpy as np
import torch
from PIL import Image

INPUT_WIDTH = 160
INPUT_HEIGHT = 120
# Preprocessing shared with the YAML: x = (rgb - MEAN) * SCALE.
MEAN = 127.5
SCALE = 1.0 / 127.5
# Output stride of the network.
STRIDE = 4
IGNORE = 255


class TinyMaterialNet(torch.nn.Module):
    """Four 3x3 convolutions (two with stride 2, one dilated) and a 1x1 classifier: about 25k parameters."""

    def __init__(self, num_labels):
        super().__init__()
        self.features = torch.nn.Sequential(
            torch.nn.Conv2d(3, 16, 3, padding=1), torch.nn.ReLU(),
            torch.nn.Conv2d(16, 24, 3, stride=2, padding=1), torch.nn.ReLU(),
            torch.nn.Conv2d(24, 32, 3, stride=2, padding=1), torch.nn.ReLU(),
            torch.nn.Conv2d(32, 32, 3, padding=2, dilation=2), torch.nn.ReLU(),
            torch.nn.Conv2d(32, 32, 3, padding=4, dilation=4), torch.nn.ReLU(),
        )
        self.classifier = torch.nn.Conv2d(32, num_labels, 1)

    def forward(self, x):
        return self.classifier(self.features(x))


def load_dataset(folder):
    labels_path = os.path.join(folder, "labels.txt")
    if not os.path.exists(labels_path):
        sys.exit(f"train_material_net: {labels_path} is missing; create the data with `cairn friction-dataset`.")
    with open(labels_path) as f:
        labels = [line.strip() for line in f if line.strip()]
    image_paths = sorted(glob.glob(os.path.join(folder, "image_*.png")))
    if not image_paths:
        sys.exit(f"train_material_net: no image_*.png in {folder}.")
    images, targets = [], []
    for path in image_paths:
        label_path = path.replace("image_", "label_")
        rgb = np.asarray(Image.open(path).convert("RGB").resize((INPUT_WIDTH, INPUT_HEIGHT), Image.BILINEAR),
                         dtype=np.float32)
        label = np.asarray(Image.open(label_path).resize((INPUT_WIDTH, INPUT_HEIGHT), Image.NEAREST),
                           dtype=np.int64)
        images.append(((rgb - MEAN) * SCALE).transpose(2, 0, 1))
        # Targets at the output resolution: the label at each output cell's centre.
        targets.append(label[STRIDE // 2::STRIDE, STRIDE // 2::STRIDE])
    return labels, torch.tensor(np.stack(images)), torch.tensor(np.stack(targets))


def accuracy(model, x, y, num_labels):
    with torch.no_grad():
        predicted = model(x).argmax(1)
    valid = y != IGNORE
    correct = (predicted == y) & valid
    pixel = correct.sum().item() / max(1, valid.sum().item())
    per_class = []
    for k in range(num_labels):
        total = ((y == k) & valid).sum().item()
        if total:
            per_class.append(((predicted == k) & (y == k)).sum().item() / total)
    return pixel, float(np.mean(per_class)) if per_class else 0.0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--data", required=True, help="folder written by `cairn friction-dataset`")
    parser.add_argument("--out", required=True, help="output path without extension (.onnx and .yaml are added)")
    parser.add_argument("--epochs", type=int, default=60)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--holdout", type=float, default=0.2, help="fraction of images (the last) held out")
    args = parser.parse_args()

    torch.manual_seed(args.seed)
    torch.set_num_threads(2)
    torch.use_deterministic_algorithms(True)
    labels, x, y = load_dataset(args.data)
    n_test = max(1, int(round(args.holdout * len(x))))
    x_train, y_train, x_test, y_test = x[:-n_test], y[:-n_test], x[-n_test:], y[-n_test:]

    # Class weights so that rare materials count (class-average accuracy is the harder figure).
    counts = torch.bincount(y_train[y_train != IGNORE].flatten(), minlength=len(labels)).float()
    weights = torch.where(counts > 0, counts.sum() / (counts.clamp(min=1) * (counts > 0).sum()), torch.zeros(1))
    model = TinyMaterialNet(len(labels))
    loss_fn = torch.nn.CrossEntropyLoss(weight=weights, ignore_index=IGNORE)
    optimiser = torch.optim.Adam(model.parameters(), lr=3e-3)
    scheduler = torch.optim.lr_scheduler.CosineAnnealingLR(optimiser, T_max=args.epochs)
    generator = torch.Generator().manual_seed(args.seed)
    for epoch in range(args.epochs):
        model.train()
        order = torch.randperm(len(x_train), generator=generator)
        total = 0.0
        for start in range(0, len(order), 16):
            batch = order[start:start + 16]
            xb, yb = x_train[batch], y_train[batch]
            if torch.rand(1, generator=generator).item() < 0.5:
                xb, yb = xb.flip(3), yb.flip(2)
            optimiser.zero_grad()
            loss = loss_fn(model(xb), yb)
            loss.backward()
            optimiser.step()
            total += loss.item() * len(batch)
        scheduler.step()
        if epoch % 10 == 9 or epoch == args.epochs - 1:
            model.eval()
            pixel, class_average = accuracy(model, x_test, y_test, len(labels))
            print(f"epoch {epoch + 1}: loss {total / len(x_train):.3f}, held-out pixel accuracy {pixel:.3f}, "
                  f"class-average {class_average:.3f}")

    model.eval()
    pixel, class_average = accuracy(model, x_test, y_test, len(labels))
    onnx_path = args.out + ".onnx"
    torch.onnx.export(model, torch.zeros(1, 3, INPUT_HEIGHT, INPUT_WIDTH), onnx_path, opset_version=11,
                      input_names=["image"], output_names=["scores"])
    import onnx  # Checked after export: a malformed graph fails here rather than in Cairn's tests.
    onnx.checker.check_model(onnx.load(onnx_path))
    with open(args.out + ".yaml", "w") as f:
        f.write("# Tiny material segmentation network trained by scripts/train_material_net.py on Cairn's rendered\n")
        f.write("# material scenes; read by cairn::perception::OnnxMaterialSegmenter.\n")
        f.write(f"model: {os.path.basename(onnx_path)}\n")
        f.write("labels: [" + ", ".join(labels) + "]\n")
        f.write("input:\n")
        f.write(f"  width: {INPUT_WIDTH}\n  height: {INPUT_HEIGHT}\n  channel_order: rgb\n")
        f.write(f"  mean: [{MEAN}, {MEAN}, {MEAN}]\n  scale: {SCALE!r}\n")
        f.write("training:\n")
        f.write(f"  images: {len(x_train)}\n  held_out_images: {len(x_test)}\n  epochs: {args.epochs}\n"
                f"  seed: {args.seed}\n")
        f.write(f"  held_out_pixel_accuracy: {pixel:.4f}\n  held_out_class_average_accuracy: {class_average:.4f}\n")
    print(f"wrote {onnx_path} ({os.path.getsize(onnx_path)} bytes) and {args.out}.yaml; held-out pixel accuracy "
          f"{pixel:.3f}, class-average {class_average:.3f}")


if __name__ == "__main__":
    main()
