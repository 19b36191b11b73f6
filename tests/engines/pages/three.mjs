// three.js r187 reads a bake made with --profile threejs and renders a row of spheres into a
// float target, read back linear: no tone mapping, no output transform.
import * as THREE from '/node_modules/three/build/three.module.js';
import { read } from '/node_modules/ktx-parse/dist/index.mjs';
import { bakedLights } from './lights.mjs';

const VK_FORMAT_R16G16B16A16_SFLOAT = 97;

async function fetchBytes(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: ${response.status}`);
  return new Uint8Array(await response.arrayBuffer());
}

// The loader docs/engines.md shows: ktx-parse, then a CompressedCubeTexture marked as a PMREM,
// which three.js samples as it is (r = 0 at mip 0, r = 1 at the last).
export async function loadPrefilteredCube(url, { mirrorX = false } = {}) {
  const container = read(await fetchBytes(url));
  if (container.faceCount !== 6 || container.vkFormat !== VK_FORMAT_R16G16B16A16_SFLOAT)
    throw new Error(`${url}: not an RGBA16F cube`);
  const faces = [];
  for (let face = 0; face < 6; face++) {
    const mipmaps = container.levels.map((level, mip) => {
      const width = Math.max(container.pixelWidth >> mip, 1);
      const faceBytes = level.levelData.byteLength / 6;
      // mirrorX (the tests' mutation only): the kit's frame turned into three.js's here instead.
      const source = mirrorX ? [1, 0, 2, 3, 4, 5][face] : face;
      const bytes = level.levelData.subarray(source * faceBytes, (source + 1) * faceBytes);
      const data = new Uint16Array(bytes.slice().buffer);
      return { data: mirrorX ? mirrorColumns(data, width) : data, width, height: width };
    });
    faces.push({ mipmaps, width: container.pixelWidth, height: container.pixelHeight });
  }
  const texture = new THREE.CompressedCubeTexture(faces, THREE.RGBAFormat, THREE.HalfFloatType);
  texture.minFilter = THREE.LinearMipmapLinearFilter;
  texture.magFilter = THREE.LinearFilter;
  texture.generateMipmaps = false;
  texture.isPMREMTexture = true;
  texture.needsUpdate = true;
  return texture;
}

function mirrorColumns(texels, width) {
  const mirrored = new Uint16Array(texels.length);
  for (let row = 0; row < width; row++)
    for (let column = 0; column < width; column++)
      mirrored.set(texels.subarray((row * width + column) * 4, (row * width + column + 1) * 4),
                   (row * width + width - 1 - column) * 4);
  return mirrored;
}

// lights.gltf's directional lights (KHR_lights_punctual): colour × intensity is the irradiance
// three.js lights with; the light shines from extras.direction.
async function loadLights(bake) {
  return (await bakedLights(bake)).map((light) => {
    const three = new THREE.DirectionalLight(new THREE.Color().setRGB(...light.color, THREE.LinearSRGBColorSpace),
                                             light.intensity);
    three.position.set(...light.extras.direction);
    return three;
  });
}

// spheres: [{ color: [r, g, b], metalness, roughness, column, row }], radius 1, one per cell of
// `cell` pixels spanning ±`span` about the sphere's centre (row 0 at the top; left to right when no
// cell is given), seen by an orthographic camera looking down -Z: the kit's render's grid has
// span 1 / 0.9 (hlsl/Common/SphereGrid.fxh).
async function renderSpheres({ bake, spheres, cell, span = 1, lights = true, mirrorX = false }) {
  const placed = spheres.map((sphere, index) => ({ column: index, row: 0, ...sphere }));
  const columns = Math.max(...placed.map((s) => s.column)) + 1, rows = Math.max(...placed.map((s) => s.row)) + 1;
  const canvas = document.getElementById('canvas');
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: false });
  renderer.toneMapping = THREE.NoToneMapping;
  const scene = new THREE.Scene();
  scene.environment = await loadPrefilteredCube(`${bake}/specular.ktx2`, { mirrorX });
  if (lights) for (const light of await loadLights(bake)) scene.add(light);
  const geometry = new THREE.SphereGeometry(1, 256, 128);
  for (const sphere of placed) {
    const material = new THREE.MeshStandardMaterial({
      color: new THREE.Color().setRGB(...sphere.color, THREE.LinearSRGBColorSpace),
      metalness: sphere.metalness, roughness: sphere.roughness });
    const mesh = new THREE.Mesh(geometry, material);
    mesh.position.set(2 * span * sphere.column, -2 * span * sphere.row, 0);
    scene.add(mesh);
  }
  const width = cell * columns, height = cell * rows;
  const camera = new THREE.OrthographicCamera(-span, span * (2 * columns - 1), span, span * (1 - 2 * rows), 0.1, 10);
  camera.position.set(0, 0, 5);
  const target = new THREE.WebGLRenderTarget(width, height, { type: THREE.FloatType });
  renderer.setRenderTarget(target);
  renderer.setClearColor(0x000000, 0);
  renderer.render(scene, camera);
  const pixels = new Float32Array(width * height * 4);
  renderer.readRenderTargetPixels(target, 0, 0, width, height, pixels);
  renderer.dispose();
  return { width, height, pixels: Array.from(pixels) };
}

window.iblkitRender = renderSpheres;
window.iblkitReady = true;
