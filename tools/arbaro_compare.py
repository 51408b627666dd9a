#!/usr/bin/env python3
"""Helpers of tools/arbaro_compare.sh (needs Pillow for `compose`: apt-get install -y python3-pil).

  arbaro_compare.py camera SKELETON.json WIDTH HEIGHT
      prints `arbor render --camera` for a side view (from -y, as Arbaro's POV export is seen) of the whole tree:
      a narrow field of view from far away, so the picture is nearly orthographic like Arbaro's, framed on the
      skeleton's nodes and leaves with 6 % margins.
  arbaro_compare.py compose ARBARO.png ARBOR.png TITLE OUT.png
      puts the two renders side by side under their captions and writes a palette PNG (kept small for docs/).
"""
import json
import math
import sys


def camera(skeleton_path, width, height):
    with open(skeleton_path) as f:
        skeleton = json.load(f)
    points = [n["position"] for n in skeleton["nodes"]] + [leaf["position"] for leaf in skeleton["leaves"]]
    lo = [min(p[i] for p in points) for i in range(3)]
    hi = [max(p[i] for p in points) for i in range(3)]
    fov = 8.0
    bottom = min(lo[2], 0.0)
    span_y = (hi[2] - bottom) * 1.12
    span_x = (hi[0] - lo[0]) * 1.12
    up = max(span_y, span_x * height / width)
    distance = up / 2 / math.tan(math.radians(fov / 2))  # frames the plane through the trunk (y = 0)
    cx, cz = (lo[0] + hi[0]) / 2, (hi[2] + bottom) / 2
    return f"{cx:.4f},{-distance:.4f},{cz:.4f},{cx:.4f},0,{cz:.4f},{fov}"


def compose(arbaro_path, arbor_path, title, out_path):
    from PIL import Image, ImageDraw

    left, right = Image.open(arbaro_path).convert("RGB"), Image.open(arbor_path).convert("RGB")
    caption = 22
    w, h = left.width + right.width, max(left.height, right.height) + caption
    sheet = Image.new("RGB", (w, h), (255, 255, 255))
    sheet.paste(left, (0, caption))
    sheet.paste(right, (left.width, caption))
    draw = ImageDraw.Draw(sheet)
    draw.text((6, 5), f"Arbaro 1.9.9 + POV-Ray: {title}", fill=(0, 0, 0))
    draw.text((left.width + 6, 5), "Arbor (lavapipe, ACC, leaves)", fill=(0, 0, 0))
    draw.line([(left.width, 0), (left.width, h)], fill=(255, 255, 255), width=2)
    sheet.quantize(colors=128, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE).save(out_path, optimize=True)


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "camera":
        print(camera(sys.argv[2], int(sys.argv[3]), int(sys.argv[4])))
    elif len(sys.argv) == 6 and sys.argv[1] == "compose":
        compose(*sys.argv[2:])
    else:
        sys.exit(__doc__)
