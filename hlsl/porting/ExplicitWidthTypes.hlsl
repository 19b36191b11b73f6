// Shader Model 6.2's 32- and 64-bit explicit-width names, C's `unsigned int`, vector<T, N> and
// matrix<T, R, C> of minimum-precision types reached through typedefs, as FidelityFX-style type
// headers write them, and a minimum-precision matrix (min16float2x2), on values read at run time.
typedef vector<min16float, 2> Half2;
typedef matrix<float32_t, 2, 2> Float2x2;
StructuredBuffer<float32_t> In : register(t0);
RWStructuredBuffer<float32_t> Out : register(u0);

static const unsigned int kCount = 2;

[numthreads(1, 1, 1)]
void main()
{
    const Half2 pair = Half2(In[0], In[1]);
    const Float2x2 rotation = Float2x2(0.0, -1.0, 1.0, 0.0);
    const min16float2x2 doubling = min16float2x2(2.0, 0.0, 0.0, 2.0);
    const vector<float32_t, 2> turned = mul(doubling, mul(rotation, float32_t2(pair)));
    const uint32_t scaled = (uint32_t)In[2] * kCount;
    const float64_t wide = (float64_t)In[3] * 3.0;
    Out[0] = turned.x;
    Out[1] = turned.y;
    Out[2] = (float32_t)scaled;
    Out[3] = (float32_t)wide;
}
