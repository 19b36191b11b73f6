// Wave intrinsics in a pixel shader: the lane index and count are integer inputs, which Vulkan
// requires to be Flat (glslang leaves the decoration off).
float4 main(float4 position : SV_Position) : SV_Target0
{
    return float4(WaveGetLaneIndex(), WaveGetLaneCount(), WaveIsFirstLane() ? 1.0 : 0.0, position.x);
}
