#!/usr/bin/env python3
# Makes height_field_gif.scn's GIF here (it is committed; run this again only
# to change it): a 48x48 hill of palette indices whose palette scrambles the
# colours, so that heights read from the colours (OpenImageIO's) and from the
# indices (POV-Ray's) differ everywhere. The LZW stream starts over every 200
# pixels, so each code is 9 bits: no compression, and no encoder needed.
import math, os, struct

W = H = 48
pixels = [min(255, int(255 * math.exp(-((x - 20) ** 2 + (y - 26) ** 2) / 180.0))) for y in range(H) for x in range(W)]
palette = b''.join(bytes(((i * 37) % 256, (i * 101) % 256, (i * 173) % 256)) for i in range(256))

codes = []
for i, p in enumerate(pixels):
    if i % 200 == 0:
        codes.append(256)   # clear
    codes.append(p)
codes.append(257)           # end
bits = acc = 0
data = bytearray()
for c in codes:
    acc |= c << bits
    bits += 9
    while bits >= 8:
        data.append(acc & 255)
        acc >>= 8
        bits -= 8
if bits:
    data.append(acc & 255)
blocks = b''.join(bytes([len(data[i:i + 255])]) + data[i:i + 255] for i in range(0, len(data), 255))
gif = (b'GIF89a' + struct.pack('<HHBBB', W, H, 0xF7, 0, 0) + palette +
       b'\x2c' + struct.pack('<HHHHB', 0, 0, W, H, 0) + b'\x08' + blocks + b'\x00\x3b')
with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), 'hill.gif'), 'wb') as f:
    f.write(gif)
