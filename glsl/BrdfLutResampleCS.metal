#pragma clang diagnostic ignored "-Wmissing-prototypes"
#pragma clang diagnostic ignored "-Wmissing-braces"

#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

template<typename T, size_t Num>
struct spvUnsafeArray
{
    T elements[Num ? Num : 1];
    
    thread T& operator [] (size_t pos) thread
    {
        return elements[pos];
    }
    constexpr const thread T& operator [] (size_t pos) const thread
    {
        return elements[pos];
    }
    
    device T& operator [] (size_t pos) device
    {
        return elements[pos];
    }
    constexpr const device T& operator [] (size_t pos) const device
    {
        return elements[pos];
    }
    
    constexpr const constant T& operator [] (size_t pos) const constant
    {
        return elements[pos];
    }
    
    threadgroup T& operator [] (size_t pos) threadgroup
    {
        return elements[pos];
    }
    constexpr const threadgroup T& operator [] (size_t pos) const threadgroup
    {
        return elements[pos];
    }
};

struct Grid
{
    float2 _data[1];
};

struct LutGridParameter
{
    uint GridSize;
};

kernel void main0(constant LutGridParameter& _228 [[buffer(0)]], const device Grid& Grid_1 [[buffer(1)]], texture2d<float, access::write> Precomputed [[texture(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint2 _367 = uint2(0u);
        uint2 _368 = uint2(Precomputed.get_width(), Precomputed.get_height());
        _367.x = _368.x;
        _367.y = _368.y;
        if (any(gl_GlobalInvocationID.xy >= _367))
        {
            break;
        }
        int2 _414 = int2(int(_228.GridSize));
        int2 _369 = _414 - int2(1);
        float2 _441 = float2(pow((float(param.x) + 0.5) / float(_367.x), 0.3333333432674407958984375) * float(uint(_369.x)), pow((float(param.y) + 0.5) / float(_367.y), 0.3333333432674407958984375) * float(uint(_369.y)));
        float2 _370 = _441;
        int2 _375 = min(int2(_441), (_414 - int2(2)));
        float _453 = _370.x - float(_375.x);
        float _526 = _453 * _453;
        float _529 = _526 * _453;
        float4 _554 = float4(fma(-_526, _453, fma(2.0, _526, -_453)), fma(3.0, _529, fma(-5.0, _526, 2.0)), fma(-3.0, _529, fma(4.0, _526, _453)), fma(_526, _453, -_526)) * 0.5;
        float _460 = _370.y - float(_375.y);
        float _561 = _460 * _460;
        float _564 = _561 * _460;
        int _603 = clamp(_375.y - 1, 0, _369.y) * (_369.x + 1);
        int _611 = _603 + _375.x;
        int _615 = (_603 + _375.x) + 1;
        int _621 = _603 + min((_375.x + 2), _369.x);
        float4 _597 = _554;
        float2 _729;
        if (_375.x == 0)
        {
            _729 = ((Grid_1._data[_611] * 3.0) - (Grid_1._data[_615] * 3.0)) + Grid_1._data[_621];
        }
        else
        {
            _729 = Grid_1._data[_603 + max((_375.x - 1), 0)];
        }
        float2 _731;
        if (_375.x == (_369.x - 1))
        {
            _731 = ((Grid_1._data[_615] * 3.0) - (Grid_1._data[_611] * 3.0)) + _729;
        }
        else
        {
            _731 = Grid_1._data[_621];
        }
        spvUnsafeArray<float2, 4> _381;
        _381[0] = (((_729 * _597.x) + (Grid_1._data[_611] * _597.y)) + (Grid_1._data[_615] * _597.z)) + (_731 * _597.w);
        int _754 = clamp(_375.y, 0, _369.y) * (_369.x + 1);
        int _758 = _754 + _375.x;
        int _760 = (_754 + _375.x) + 1;
        int _763 = _754 + min((_375.x + 2), _369.x);
        _597 = _554;
        float2 _779;
        if (_375.x == 0)
        {
            _779 = ((Grid_1._data[_758] * 3.0) - (Grid_1._data[_760] * 3.0)) + Grid_1._data[_763];
        }
        else
        {
            _779 = Grid_1._data[_754 + max((_375.x - 1), 0)];
        }
        float2 _788;
        if (_375.x == (_369.x - 1))
        {
            _788 = ((Grid_1._data[_760] * 3.0) - (Grid_1._data[_758] * 3.0)) + _779;
        }
        else
        {
            _788 = Grid_1._data[_763];
        }
        _381[1] = (((_779 * _597.x) + (Grid_1._data[_758] * _597.y)) + (Grid_1._data[_760] * _597.z)) + (_788 * _597.w);
        int _824 = clamp(_375.y + 1, 0, _369.y) * (_369.x + 1);
        int _828 = _824 + _375.x;
        int _830 = (_824 + _375.x) + 1;
        int _833 = _824 + min((_375.x + 2), _369.x);
        _597 = _554;
        float2 _849;
        if (_375.x == 0)
        {
            _849 = ((Grid_1._data[_828] * 3.0) - (Grid_1._data[_830] * 3.0)) + Grid_1._data[_833];
        }
        else
        {
            _849 = Grid_1._data[_824 + max((_375.x - 1), 0)];
        }
        float2 _858;
        if (_375.x == (_369.x - 1))
        {
            _858 = ((Grid_1._data[_830] * 3.0) - (Grid_1._data[_828] * 3.0)) + _849;
        }
        else
        {
            _858 = Grid_1._data[_833];
        }
        _381[2] = (((_849 * _597.x) + (Grid_1._data[_828] * _597.y)) + (Grid_1._data[_830] * _597.z)) + (_858 * _597.w);
        int _894 = clamp(_375.y + 2, 0, _369.y) * (_369.x + 1);
        int _898 = _894 + _375.x;
        int _900 = (_894 + _375.x) + 1;
        int _903 = _894 + min((_375.x + 2), _369.x);
        _597 = _554;
        float2 _919;
        if (_375.x == 0)
        {
            _919 = ((Grid_1._data[_898] * 3.0) - (Grid_1._data[_900] * 3.0)) + Grid_1._data[_903];
        }
        else
        {
            _919 = Grid_1._data[_894 + max((_375.x - 1), 0)];
        }
        float2 _928;
        if (_375.x == (_369.x - 1))
        {
            _928 = ((Grid_1._data[_900] * 3.0) - (Grid_1._data[_898] * 3.0)) + _919;
        }
        else
        {
            _928 = Grid_1._data[_903];
        }
        _381[3] = (((_919 * _597.x) + (Grid_1._data[_898] * _597.y)) + (Grid_1._data[_900] * _597.z)) + (_928 * _597.w);
        float4 _393 = float4(fma(-_561, _460, fma(2.0, _561, -_460)), fma(3.0, _564, fma(-5.0, _561, 2.0)), fma(-3.0, _564, fma(4.0, _561, _460)), fma(_561, _460, -_561)) * 0.5;
        float2 _725;
        if (_375.y == 0)
        {
            _725 = ((_381[1] * 3.0) - (_381[2] * 3.0)) + _381[3];
        }
        else
        {
            _725 = _381[0];
        }
        float2 _727;
        if (_375.y == (_369.y - 1))
        {
            _727 = ((_381[2] * 3.0) - (_381[1] * 3.0)) + _725;
        }
        else
        {
            _727 = _381[3];
        }
        Precomputed.write(((((_725 * _393.x) + (_381[1] * _393.y)) + (_381[2] * _393.z)) + (_727 * _393.w)).xyyy, uint2(gl_GlobalInvocationID.xy));
        break;
    } while(false);
}

