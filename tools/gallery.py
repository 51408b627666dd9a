#!/usr/bin/env python3
"""Lays renders out as a captioned grid for docs/ (needs Pillow: apt-get install -y python3-pil).

  gallery.py OUT.png COLUMNS CAPTION=IMAGE.png ...
      puts the images in rows of COLUMNS, each under its caption, and writes a palette PNG (kept small for docs/).
"""
import sys


def font(size):
    from PIL import ImageFont

    # DejaVu where Debian has it (fonts-dejavu-core), else Pillow's own bitmap font.
    try:
        return ImageFont.truetype("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", size)
    except OSError:
        return ImageFont.load_default()


def gallery(out_path, columns, entries):
    from PIL import Image, ImageDraw

    images = [(caption, Image.open(path).convert("RGB")) for caption, path in entries]
    cell_w = max(image.width for _, image in images)
    cell_h = max(image.height for _, image in images)
    caption_h = 20
    rows = (len(images) + columns - 1) // columns
    sheet = Image.new("RGB", (columns * cell_w, rows * (cell_h + caption_h)), (255, 255, 255))
    draw = ImageDraw.Draw(sheet)
    text = font(12)
    for i, (caption, image) in enumerate(images):
        x, y = (i % columns) * cell_w, (i // columns) * (cell_h + caption_h)
        draw.text((x + 5, y + 3), caption, fill=(0, 0, 0), font=text)
        sheet.paste(image, (x, y + caption_h))
    sheet.quantize(colors=192, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE).save(out_path, optimize=True)


if __name__ == "__main__":
    if len(sys.argv) < 4 or not sys.argv[2].isdigit() or int(sys.argv[2]) < 1 or any("=" not in a for a in sys.argv[3:]):
        sys.exit(__doc__)
    gallery(sys.argv[1], int(sys.argv[2]), [tuple(a.split("=", 1)) for a in sys.argv[3:]])
