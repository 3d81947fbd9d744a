#!/usr/bin/python3
"""Checks that an rviz screenshot (scripts/rviz-screenshot.sh) shows a map.

Passes when the picture is not uniform, rviz drew its 3D view (the largest connected area of the background
colour 48,48,48 of launch/ppp.rviz: the margin around the map, so the map must not fill the whole view), and
inside that view many pixels have the map's free colour (near white) and some its obstacle colour (near black). Prints what it measured; exit status 0 on success, 1 when the picture fails, 2 on bad usage.

Usage: scripts/check_screenshot.py PNG [--min-free FRACTION] [--min-obstacle FRACTION]
"""
import argparse
import sys

try:
    from PIL import Image
except ImportError:
    sys.exit('check_screenshot: needs python3-pil (scripts/install-deps.sh installs it)')

BACKGROUND = (48, 48, 48)  # Global Options / Background Color of launch/ppp.rviz


def grey(pixel, low, high):
    """True for a neutral grey whose channels all lie in [low, high]."""
    return max(pixel) - min(pixel) <= 12 and low <= min(pixel) and max(pixel) <= high


def largest_region(mask, width, height):
    """Bounding box (x0, y0, x1, y1) and size of the largest 4-connected region of set cells in `mask`."""
    seen = bytearray(width * height)
    best = (None, 0)
    for start in range(width * height):
        if not mask[start] or seen[start]:
            continue
        seen[start] = 1
        stack = [start]
        count = 0
        x0, y0, x1, y1 = width, height, -1, -1
        while stack:
            i = stack.pop()
            count += 1
            x, y = i % width, i // width
            x0, y0, x1, y1 = min(x0, x), min(y0, y), max(x1, x), max(y1, y)
            for j in (i - 1 if x > 0 else -1, i + 1 if x + 1 < width else -1, i - width, i + width):
                if 0 <= j < width * height and mask[j] and not seen[j]:
                    seen[j] = 1
                    stack.append(j)
        if count > best[1]:
            best = ((x0, y0, x1 + 1, y1 + 1), count)
    return best


def measure(image):
    """Counts of the picture: distinct colours, the 3D view's box and its free and obstacle pixels. The 3D view
    is the bounding box of the largest connected area of background colour (the margin around the map)."""
    rgb = image.convert('RGB')
    width, height = rgb.size
    pixels = rgb.load()
    colours = rgb.getcolors(maxcolors=width * height)
    step = 2  # the view is found on a half-resolution grid
    w, h = width // step, height // step
    mask = bytearray(1 if pixels[x * step, y * step] == BACKGROUND else 0 for y in range(h) for x in range(w))
    box, count = largest_region(mask, w, h)
    result = {'size': (width, height), 'colours': len(colours), 'background': count * step * step, 'view': None,
              'free': 0, 'obstacle': 0}
    if box is None:
        return result
    box = tuple(v * step for v in box)
    result['view'] = box
    for y in range(box[1], box[3]):
        for x in range(box[0], box[2]):
            p = pixels[x, y]
            if grey(p, 200, 255):
                result['free'] += 1
            elif grey(p, 0, 20):
                result['obstacle'] += 1
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('png')
    parser.add_argument('--min-free', type=float, default=0.05,
                        help='smallest share of the 3D view in the free colour (default 0.05)')
    parser.add_argument('--min-obstacle', type=float, default=0.002,
                        help='smallest share of the 3D view in the obstacle colour (default 0.002)')
    args = parser.parse_args()
    try:
        image = Image.open(args.png)
    except OSError as e:
        print('check_screenshot: %s: cannot read the picture: %s' % (args.png, e), file=sys.stderr)
        return 1
    m = measure(image)
    print('check_screenshot: %s: %dx%d, %d colours, 3D view %s, free %d px, obstacle %d px' %
          (args.png, m['size'][0], m['size'][1], m['colours'], m['view'], m['free'], m['obstacle']))
    problems = []
    if m['colours'] < 16:
        problems.append('the picture is (nearly) uniform: %d colours' % m['colours'])
    area = 0
    if m['view'] is None or m['background'] < 0.01 * m['size'][0] * m['size'][1]:
        problems.append('no rviz 3D view (background %s) found' % (BACKGROUND,))
    else:
        box = m['view']
        area = (box[2] - box[0]) * (box[3] - box[1])
        if m['free'] < args.min_free * area:
            problems.append('too few map free pixels: %d < %.3f of the view' % (m['free'], args.min_free))
        if m['obstacle'] < args.min_obstacle * area:
            problems.append('too few map obstacle pixels: %d < %.4f of the view' % (m['obstacle'], args.min_obstacle))
    for problem in problems:
        print('check_screenshot: %s: %s' % (args.png, problem), file=sys.stderr)
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
