// [[vk::location]] on a pixel shader's input and output.
float4 main([[vk::location(2)]] float4 colour : COLOR0) : SV_Target0
{
    return colour * 0.5;
}
