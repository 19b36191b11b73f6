// Babylon.js 9 reads a bake made with --profile babylon (its DDS through its own loader) and
// renders spheres into a float target, read back linear: no image processing.
// The modules the page uses, not the package's index.js: that one imports about 3,100 modules, each
// served through request interception (16 s to open the page), these about 280.
import { Camera } from '/node_modules/@babylonjs/core/Cameras/camera.js';
import { FreeCamera } from '/node_modules/@babylonjs/core/Cameras/freeCamera.js';
import { Constants } from '/node_modules/@babylonjs/core/Engines/constants.js';
import { Engine } from '/node_modules/@babylonjs/core/Engines/engine.js';
import { DirectionalLight } from '/node_modules/@babylonjs/core/Lights/directionalLight.js';
import { PBRMaterial } from '/node_modules/@babylonjs/core/Materials/PBR/pbrMaterial.js';
import '/node_modules/@babylonjs/core/Materials/Textures/baseTexture.polynomial.js';
import { CubeTexture } from '/node_modules/@babylonjs/core/Materials/Textures/cubeTexture.js';
import '/node_modules/@babylonjs/core/Materials/Textures/Loaders/ddsTextureLoader.js';
import { RenderTargetTexture } from '/node_modules/@babylonjs/core/Materials/Textures/renderTargetTexture.js';
import { Color3, Color4 } from '/node_modules/@babylonjs/core/Maths/math.color.js';
import { Vector3 } from '/node_modules/@babylonjs/core/Maths/math.vector.js';
import { CreateSphere } from '/node_modules/@babylonjs/core/Meshes/Builders/sphereBuilder.js';
import { Scene } from '/node_modules/@babylonjs/core/scene.js';
import { bakedLights } from './lights.mjs';

// lights.gltf's directional lights (KHR_lights_punctual): Babylon.js's DirectionalLight takes the
// direction the light travels, and its intensity as the illuminance (lux) of a PBR scene.
async function addLights(bake, scene) {
  (await bakedLights(bake)).forEach((light, index) => {
    const towards = new Vector3(...light.extras.direction);
    const sun = new DirectionalLight(`light${index}`, towards.scale(-1), scene);
    sun.diffuse = new Color3(...light.color);
    sun.specular = new Color3(...light.color);
    sun.intensity = light.intensity;
  });
}

// spheres: [{ color: [r, g, b], metalness, roughness, column, row }], radius 1, one per cell of
// `cell` pixels spanning ±`span` about the sphere's centre (row 0 at the top), seen by an
// orthographic camera looking down -Z in a right-handed scene.
async function renderSpheres({ bake, spheres, cell, span = 1, lights = true }) {
  const placed = spheres.map((sphere, index) => ({ column: index, row: 0, ...sphere }));
  const columns = Math.max(...placed.map((s) => s.column)) + 1, rows = Math.max(...placed.map((s) => s.row)) + 1;
  const width = cell * columns, height = cell * rows;
  const canvas = document.getElementById('canvas');
  const engine = new Engine(canvas, false, { preserveDrawingBuffer: true });
  const scene = new Scene(engine);
  scene.useRightHandedSystem = true;
  scene.clearColor = new Color4(0, 0, 0, 0);
  // Linear, unclamped values: image processing is left to a post-process, which a render target
  // does not run (the material's own path would apply gamma and clamp to [0, 1]).
  scene.imageProcessingConfiguration.applyByPostProcess = true;
  scene.imageProcessingConfiguration.skipFinalColorClamp = true;
  const environment = CubeTexture.CreateFromPrefilteredData(`${bake}/specular.dds`, scene);
  scene.environmentTexture = environment;
  await new Promise((resolve, reject) => {
    environment.onLoadObservable.addOnce(resolve);
    setTimeout(() => reject(new Error('specular.dds did not load')), 60000);
  });
  if (lights) await addLights(bake, scene);
  // Babylon.js's PBR shading takes the view direction from the eye's position, orthographic camera
  // or not: far away, every view direction is -Z within 0.1°.
  const camera = new FreeCamera('camera', new Vector3(0, 0, 1e4), scene);
  camera.setTarget(new Vector3(0, 0, 0));
  camera.mode = Camera.ORTHOGRAPHIC_CAMERA;
  [camera.orthoLeft, camera.orthoRight, camera.orthoTop, camera.orthoBottom] =
    [-span, span * (2 * columns - 1), span, span * (1 - 2 * rows)];
  camera.minZ = 1e4 - 10;
  camera.maxZ = 1e4 + 10;
  const meshes = placed.map((sphere, index) => {
    const mesh = CreateSphere(`sphere${index}`, { diameter: 2, segments: 128 }, scene);
    mesh.position.set(2 * span * sphere.column, -2 * span * sphere.row, 0);
    const material = new PBRMaterial(`material${index}`, scene);
    material.albedoColor = new Color3(...sphere.color);
    material.metallic = sphere.metalness;
    material.roughness = sphere.roughness;
    mesh.material = material;
    return mesh;
  });
  const target = new RenderTargetTexture('target', { width, height }, scene, false, true,
                                                 Constants.TEXTURETYPE_FLOAT);
  target.renderList = meshes;
  target.activeCamera = camera;
  target.clearColor = new Color4(0, 0, 0, 0);
  scene.customRenderTargets.push(target);
  await scene.whenReadyAsync();
  scene.render();
  const pixels = await target.readPixels();
  engine.dispose();
  return { width, height, pixels: Array.from(new Float32Array(pixels.buffer, pixels.byteOffset, width * height * 4)) };
}

// The SH Babylon.js projects from the DDS's mip 0 as it loads it (CubeMapToSphericalPolynomialTools):
// its preScaledHarmonics, in the order l00, l1-1, l10, l11, l2-2, l2-1, l20, l21, l22.
async function sphericalHarmonics({ bake }) {
  const engine = new Engine(document.getElementById('canvas'), false);
  const scene = new Scene(engine);
  const texture = CubeTexture.CreateFromPrefilteredData(`${bake}/specular.dds`, scene);
  await new Promise((resolve) => texture.onLoadObservable.addOnce(resolve));
  const harmonics = texture.sphericalPolynomial.preScaledHarmonics;
  const coefficients = ['l00', 'l1_1', 'l10', 'l11', 'l2_2', 'l2_1', 'l20', 'l21', 'l22'].map((name) => harmonics[name].asArray());
  engine.dispose();
  return coefficients;
}

window.iblkitRender = renderSpheres;
window.iblkitSphericalHarmonics = sphericalHarmonics;
window.iblkitReady = true;
