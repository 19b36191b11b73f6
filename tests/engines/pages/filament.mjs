// Filament 1.53 (web) reads a bake made with --profile filament (its KTX1 cube through
// createTextureFromKtx1, the SH as IndirectLight's) and renders spheres from a glTF its own
// loader builds with its ubershaders, read back from the canvas: no post-processing, exposure 1.


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

// The canvas holds 8 bits a channel: `exposure` scales the light (the IBL's intensity) to keep the
// brightest pixel within 1, and the values come back divided by it.
async function renderSpheres({ bake, spheres, cell, span = 1, exposure = 1 }) {
  const Filament = window.Filament; // complete once Filament.init has called back
  const placed = spheres.map((sphere, index) => ({ column: index, row: 0, ...sphere }));
  const columns = Math.max(...placed.map((s) => s.column)) + 1, rows = Math.max(...placed.map((s) => s.row)) + 1;
  const width = cell * columns, height = cell * rows;
  const canvas = document.getElementById('canvas');
  canvas.width = width;
  canvas.height = height;
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
  renderer.setClearOptions({ clearColor: [0, 0, 0, 0], clear: true });
  camera.setProjection(Filament.Camera$Projection.ORTHO, -span, span * (2 * columns - 1), span * (1 - 2 * rows), span, 1e3 - 10, 1e3 + 10);
  camera.lookAt([0, 0, 1e3], [0, 0, 0], [0, 1, 0]);
  camera.setExposureDirect(1);
  const manifest = await (await fetch(`${bake}/manifest.json`)).json();
  const reflections = engine.createTextureFromKtx1(await fetchBytes(`${bake}/specular.ktx`), { srgb: false });
  const sh = manifest.profile.sh_coefficients.flat();
  scene.setIndirectLight(Filament.IndirectLight.Builder().reflections(reflections).irradianceSh(3, sh).intensity(exposure).build(engine));
  const loader = engine.createAssetLoader();
  const asset = loader.createAsset(spheresGltf(placed, span));
  await new Promise((resolve) => asset.loadResources(resolve, null, null, null));
  scene.addEntities(asset.getRenderableEntities());
  const gl = canvas.getContext('webgl2');
  const pixels = new Uint8Array(width * height * 4);
  for (let frame = 0; frame < 4; frame++) {
    renderer.render(swapChain, view);
    engine.execute?.();
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    await new Promise((resolve) => requestAnimationFrame(resolve));
  }
  return { width, height, pixels: Array.from(pixels, (value) => value / 255 / exposure) };
}

window.iblkitRender = renderSpheres;
window.Filament.init([], () => { window.iblkitReady = true; });
