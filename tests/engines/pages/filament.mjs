// Filament 1.53 (web) reads a bake made with --profile filament (its KTX1 cube through
// createTextureFromKtx1, the SH as IndirectLight's) and renders spheres from a glTF its own
// loader builds with its ubershaders, each light of lights.gltf as its SUN; read back as floats
// from an RGBA16F target: no post-processing, exposure 1.
import { bakedLights } from './lights.mjs';

async function fetchBytes(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: ${response.status}`);
  return new Uint8Array(await response.arrayBuffer());
}

// A UV sphere of radius 1: positions and normals (the same), 16-bit indices.
function sphereMesh(segments = 96, rings = 48) {
  const positions = [], indices = [];
  for (let ring = 0; ring <= rings; ring++) {
    const theta = (ring / rings) * Math.PI;
    for (let segment = 0; segment <= segments; segment++) {
      const phi = (segment / segments) * 2 * Math.PI;
      positions.push(Math.sin(theta) * Math.cos(phi), Math.cos(theta), -Math.sin(theta) * Math.sin(phi));
    }
  }
  for (let ring = 0; ring < rings; ring++)
    for (let segment = 0; segment < segments; segment++) {
      const a = ring * (segments + 1) + segment, b = a + segments + 1;
      indices.push(a, b, a + 1, a + 1, b, b + 1);
    }
  return { positions: new Float32Array(positions), indices: new Uint16Array(indices) };
}

function base64(bytes) {
  let text = '';
  for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(text);
}

// One glTF of every sphere, each its own material and node.
function spheresGltf(placed, span) {
  const { positions, indices } = sphereMesh();
  const buffer = new Uint8Array(positions.byteLength + indices.byteLength);
  buffer.set(new Uint8Array(positions.buffer), 0);
  buffer.set(new Uint8Array(indices.buffer), positions.byteLength);
  const gltf = {
    asset: { version: '2.0' },
    buffers: [{ byteLength: buffer.length, uri: `data:application/octet-stream;base64,${base64(buffer)}` }],
    bufferViews: [{ buffer: 0, byteOffset: 0, byteLength: positions.byteLength, target: 34962 },
                  { buffer: 0, byteOffset: positions.byteLength, byteLength: indices.byteLength, target: 34963 }],
    accessors: [{ bufferView: 0, componentType: 5126, count: positions.length / 3, type: 'VEC3', min: [-1, -1, -1], max: [1, 1, 1] },
                { bufferView: 1, componentType: 5123, count: indices.length, type: 'SCALAR' }],
    materials: placed.map((sphere) => ({ pbrMetallicRoughness: { baseColorFactor: [...sphere.color, 1],
                                                                 metallicFactor: sphere.metalness,
                                                                 roughnessFactor: sphere.roughness } })),
    meshes: placed.map((sphere, index) => ({ primitives: [{ attributes: { POSITION: 0, NORMAL: 0 }, indices: 1, material: index }] })),
    nodes: placed.map((sphere, index) => ({ mesh: index, translation: [2 * span * sphere.column, -2 * span * sphere.row, 0] })),
    scenes: [{ nodes: placed.map((sphere, index) => index) }],
    scene: 0,
  };
  return new TextEncoder().encode(JSON.stringify(gltf));
}

// Filament's web API reads no pixels back, and its canvas holds 8 bits a channel. So the view
// renders into an RGBA16F texture, and the page reads that texture's framebuffer as floats: the
// WebGL2 context's calls are watched from before Engine.create to learn which framebuffer
// Filament attaches the texture to (its GL backend names none of them to the page).
const textures = new Map(); // WebGLTexture → { format, width, height, framebuffer }
function watchFramebuffers() {
  const gl = WebGL2RenderingContext.prototype;
  const texStorage2D = gl.texStorage2D, framebufferTexture2D = gl.framebufferTexture2D;
  gl.texStorage2D = function (target, levels, format, width, height) {
    const texture = this.getParameter(this.TEXTURE_BINDING_2D);
    if (target === this.TEXTURE_2D && texture) textures.set(texture, { format, width, height });
    return texStorage2D.call(this, target, levels, format, width, height);
  };
  gl.framebufferTexture2D = function (target, attachment, textureTarget, texture, level) {
    const binding = target === this.READ_FRAMEBUFFER ? this.READ_FRAMEBUFFER_BINDING : this.DRAW_FRAMEBUFFER_BINDING;
    if (attachment === this.COLOR_ATTACHMENT0 && textures.has(texture))
      textures.get(texture).framebuffer = this.getParameter(binding);
    return framebufferTexture2D.call(this, target, attachment, textureTarget, texture, level);
  };
}
watchFramebuffers();

function floatTarget(engine, width, height) {
  const Filament = window.Filament;
  const colour = Filament.Texture.Builder().width(width).height(height).levels(1)
    .sampler(Filament.Texture$Sampler.SAMPLER_2D).format(Filament.Texture$InternalFormat.RGBA16F)
    .usage(1 | 16 /* COLOR_ATTACHMENT | SAMPLEABLE */).build(engine);
  const depth = Filament.Texture.Builder().width(width).height(height).levels(1)
    .sampler(Filament.Texture$Sampler.SAMPLER_2D).format(Filament.Texture$InternalFormat.DEPTH32F)
    .usage(2 /* DEPTH_ATTACHMENT */).build(engine);
  return Filament.RenderTarget.Builder().texture(Filament.RenderTarget$AttachmentPoint.COLOR, colour)
    .texture(Filament.RenderTarget$AttachmentPoint.DEPTH, depth).build(engine);
}

// The pixels of the RGBA16F texture of this size that Filament has attached to a framebuffer,
// as floats, bottom row first; the read framebuffer binding is put back for Filament's state cache.
function readFloatTarget(gl, width, height) {
  const matches = [...textures.values()].filter((t) => t.format === gl.RGBA16F && t.width === width &&
                                                       t.height === height && t.framebuffer);
  if (matches.length !== 1) throw new Error(`${matches.length} framebuffers hold a ${width}×${height} RGBA16F texture`);
  const previous = gl.getParameter(gl.READ_FRAMEBUFFER_BINDING);
  gl.bindFramebuffer(gl.READ_FRAMEBUFFER, matches[0].framebuffer);
  const pixels = new Float32Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, pixels);
  gl.bindFramebuffer(gl.READ_FRAMEBUFFER, previous);
  return pixels;
}

// lights.gltf's directional lights (KHR_lights_punctual) as Filament's SUN: its intensity is the
// illuminance (lux) Filament takes, exposure 1; the sun's disk is shaded at the light's angular
// radius (Filament clamps it to 0.25°-20°).
async function addSuns(bake, manifest, engine, scene) {
  const Filament = window.Filament;
  for (const light of await bakedLights(bake, manifest)) {
    const sun = Filament.EntityManager.get().create();
    Filament.LightManager.Builder(Filament.LightManager$Type.SUN).color(light.color).intensity(light.intensity)
      .direction(light.extras.direction.map((c) => -c)).sunAngularRadius((light.extras.angular_radius * 180) / Math.PI)
      .castShadows(false).build(engine, sun);
    scene.addEntity(sun);
  }
}

// Each render on a canvas of its own, with its own engine and WebGL2 context, destroyed after.
async function renderSpheres({ bake, spheres, cell, span = 1, lights = true }) {
  const Filament = window.Filament; // complete once Filament.init has called back
  const placed = spheres.map((sphere, index) => ({ column: index, row: 0, ...sphere }));
  const columns = Math.max(...placed.map((s) => s.column)) + 1, rows = Math.max(...placed.map((s) => s.row)) + 1;
  const width = cell * columns, height = cell * rows;
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  textures.clear();
  const engine = Filament.Engine.create(canvas);
  const scene = engine.createScene();
  const swapChain = engine.createSwapChain();
  const renderer = engine.createRenderer();
  const camera = engine.createCamera(Filament.EntityManager.get().create());
  const view = engine.createView();
  view.setCamera(camera);
  view.setScene(scene);
  view.setViewport([0, 0, width, height]);
  view.setPostProcessingEnabled(false);
  view.setRenderTarget(floatTarget(engine, width, height));
  renderer.setClearOptions({ clearColor: [0, 0, 0, 0], clear: true });
  camera.setProjection(Filament.Camera$Projection.ORTHO, -span, span * (2 * columns - 1), span * (1 - 2 * rows), span, 1e3 - 10, 1e3 + 10);
  camera.lookAt([0, 0, 1e3], [0, 0, 0], [0, 1, 0]);
  camera.setExposureDirect(1);
  const manifest = await (await fetch(`${bake}/manifest.json`)).json();
  const reflections = engine.createTextureFromKtx1(await fetchBytes(`${bake}/specular.ktx`), { srgb: false });
  const sh = manifest.profile.sh_coefficients.flat();
  scene.setIndirectLight(Filament.IndirectLight.Builder().reflections(reflections).irradianceSh(3, sh).intensity(1).build(engine));
  if (lights) await addSuns(bake, manifest, engine, scene);
  const loader = engine.createAssetLoader();
  const asset = loader.createAsset(spheresGltf(placed, span));
  await new Promise((resolve) => asset.loadResources(resolve, null, null, null));
  scene.addEntities(asset.getRenderableEntities());
  const gl = canvas.getContext('webgl2');
  for (let frame = 0; frame < 4; frame++) {
    renderer.render(swapChain, view);
    engine.execute?.();
    await new Promise((resolve) => requestAnimationFrame(resolve));
  }
  const pixels = Array.from(readFloatTarget(gl, width, height));
  Filament.Engine.destroy(engine);
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return { width, height, pixels };
}

window.iblkitRender = renderSpheres;
window.Filament.init([], () => { window.iblkitReady = true; });
