float4 main(float4  : SV_Position) : SV_Target { return p; }
