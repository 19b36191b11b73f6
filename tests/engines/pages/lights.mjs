// The lights a bake took out of its environment (manifest.shading.lights.file, lights.gltf's
// KHR_lights_punctual directional lights), each page turning them into its engine's own: none
// when the bake took none out.
export async function bakedLights(bake, manifest) {
  manifest ??= await (await fetch(`${bake}/manifest.json`)).json();
  const file = manifest.shading.lights.file;
  if (!file) return [];
  const gltf = await (await fetch(`${bake}/${file}`)).json();
  return gltf.extensions.KHR_lights_punctual.lights;
}
