// Buffers and constants of Shader Model 5: a structured buffer of structs read and written, a
// byte-address buffer read and written, a cbuffer, a ConstantBuffer<T>, and a struct with member
// functions.
struct Particle { float3 position; float weight; };
struct Offsets { float3 shift; };
struct Total
{
    float sum;
    void add(float value) { sum += value; }
    uint rounded() { return (uint)(sum + 0.5); }
};

cbuffer Settings : register(b0) { float Scale; };
ConstantBuffer<Offsets> Offset : register(b1);
StructuredBuffer<Particle> Particles : register(t0);
ByteAddressBuffer Extra : register(t1);
RWStructuredBuffer<Particle> Moved : register(u0);
RWByteAddressBuffer Totals : register(u1);

[numthreads(4, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    Particle particle = Particles[id.x];
    particle.position = particle.position * Scale + Offset.shift;
    Moved[id.x] = particle;
    Total total;
    total.sum = 0;
    total.add(particle.weight);
    total.add(Extra.Load(id.x * 4));
    Totals.Store(id.x * 4, total.rounded());
}
