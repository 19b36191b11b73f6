// An 8-bit RGB PNG from linear floats, with the kit's preview transform: exposure, Narkowicz's
// ACES fit, sRGB (docs/render.md).
import { writeFileSync } from 'node:fs';
import { deflateSync } from 'node:zlib';

const crcTable = Array.from({ length: 256 }, (_, n) => {
  let c = n;
  for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});

function crc32(bytes) {
  let c = 0xffffffff;
  for (const byte of bytes) c = crcTable[(c ^ byte) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

function chunk(type, data) {
  const body = Buffer.concat([Buffer.from(type, 'latin1'), data]);
  const length = Buffer.alloc(4), crc = Buffer.alloc(4);
  length.writeUInt32BE(data.length);
  crc.writeUInt32BE(crc32(body));
  return Buffer.concat([length, body, crc]);
}

function display(value, exposure) {
  const x = value * exposure;
  const aces = Math.min(1, Math.max(0, (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14)));
  const srgb = aces <= 0.0031308 ? 12.92 * aces : 1.055 * aces ** (1 / 2.4) - 0.055;
  return Math.round(255 * srgb);
}

// images: [{ width, height, pixels }] (RGBA floats, bottom row first), stacked top to bottom.
export function writePng(file, images, exposure) {
  const width = images[0].width, height = images.reduce((sum, image) => sum + image.height, 0);
  const rows = [];
  for (const image of images)
    for (let y = image.height - 1; y >= 0; y--) {
      const row = Buffer.alloc(1 + width * 3);
      for (let x = 0; x < width; x++)
        for (let c = 0; c < 3; c++) row[1 + x * 3 + c] = display(image.pixels[(y * image.width + x) * 4 + c], exposure);
      rows.push(row);
    }
  const header = Buffer.alloc(13);
  header.writeUInt32BE(width, 0);
  header.writeUInt32BE(height, 4);
  header.set([8, 2, 0, 0, 0], 8);
  writeFileSync(file, Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', header),
                                     chunk('IDAT', deflateSync(Buffer.concat(rows))), chunk('IEND', Buffer.alloc(0))]));
}
