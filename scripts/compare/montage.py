#!/usr/bin/python3
"""Puts renders side by side with a label above each (docs/gallery/compare-ez-tree.png).

  /usr/bin/python3 scripts/compare/montage.py out.png "ez-tree Oak Medium=ez-oak.png" \\
      "Sylva English oak=english-oak.png" ... [--width 160]
Needs python3-pil.
"""
import sys

from PIL import Image, ImageDraw, ImageFont


def main(argv):
    width = 160
    if "--width" in argv:
        i = argv.index("--width")
        width = int(argv[i + 1])
        del argv[i:i + 2]
    out, panels = argv[1], [a.split("=", 1) for a in argv[2:]]
    images = []
    for label, path in panels:
        img = Image.open(path).convert("RGB")
        img = img.resize((width, round(img.height * width / img.width)), Image.LANCZOS)
        images.append((label, img))
    label_h = 16
    h = max(img.height for _, img in images) + label_h
    sheet = Image.new("RGB", (width * len(images), h), (255, 255, 255))
    draw = ImageDraw.Draw(sheet)
    try:
        font = ImageFont.truetype("DejaVuSansMono-Bold.ttf", 11)
    except OSError:
        font = ImageFont.load_default()
    for k, (label, img) in enumerate(images):
        sheet.paste(img, (k * width, label_h))
        draw.text((k * width + 4, 2), label, fill=(0, 0, 0), font=font)
    sheet = sheet.quantize(colors=192, method=Image.MEDIANCUT, dither=Image.FLOYDSTEINBERG)
    sheet.save(out, optimize=True)


if __name__ == "__main__":
    main(sys.argv)
