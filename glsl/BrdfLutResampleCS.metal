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

kernel void main0(constant LutGridParameter& _209 [[buffer(0)]], const device Grid& Grid_1 [[buffer(1)]], texture2d<float, access::write> Precomputed [[texture(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint2 _385 = uint2(0u);
        uint2 _386 = uint2(Precomputed.get_width(), Precomputed.get_height());
        _385.x = _386.x;
        _385.y = _386.y;
        if (any(gl_GlobalInvocationID.xy >= _385))
        {
            break;
        }
        int2 _425 = int2(int(_209.GridSize));
        int2 _387 = _425 - int2(1);
        float2 _452 = float2(pow((float(param.x) + 0.5) / float(_385.x), 0.3333333432674407958984375) * float(uint(_387.x)), pow((float(param.y) + 0.5) / float(_385.y), 0.3333333432674407958984375) * float(uint(_387.y)));
        float2 _388 = _452;
        int2 _393 = min(int2(_452), (_425 - int2(2)));
        float _464 = _388.x - float(_393.x);
        float _581 = _464 * _464;
        float _584 = _581 * _464;
        float4 _609 = float4(fma(-_581, _464, fma(2.0, _581, -_464)), fma(3.0, _584, fma(-5.0, _581, 2.0)), fma(-3.0, _584, fma(4.0, _581, _464)), fma(_581, _464, -_581)) * 0.5;
        float _471 = _388.y - float(_393.y);
        float _616 = _471 * _471;
        float _619 = _616 * _471;
        float4 _396 = float4(fma(-_616, _471, fma(2.0, _616, -_471)), fma(3.0, _619, fma(-5.0, _616, 2.0)), fma(-3.0, _619, fma(4.0, _616, _471)), fma(_616, _471, -_616)) * 0.5;
        float4 _403 = _609;
        int _655 = clamp(_393.y - 1, 0, _387.y) * (_387.x + 1);
        int _665 = _655 + _393.x;
        int _671 = (_655 + _393.x) + 1;
        int _679 = _655 + min((_393.x + 2), _387.x);
        float2 _726;
        if (_393.x == 0)
        {
            _726 = ((Grid_1._data[_665] * 3.0) - (Grid_1._data[_671] * 3.0)) + Grid_1._data[_679];
        }
        else
        {
            _726 = Grid_1._data[_655 + max((_393.x - 1), 0)];
        }
        float2 _728;
        if (_393.x == (_387.x - 1))
        {
            _728 = ((Grid_1._data[_671] * 3.0) - (Grid_1._data[_665] * 3.0)) + _726;
        }
        else
        {
            _728 = Grid_1._data[_679];
        }
        spvUnsafeArray<float2, 4> _399;
        _399[0] = (((_726 * _403.x) + (Grid_1._data[_665] * _403.y)) + (Grid_1._data[_671] * _403.z)) + (_728 * _403.w);
        _403 = _609;
        int _751 = clamp(_393.y, 0, _387.y) * (_387.x + 1);
        int _757 = _751 + _393.x;
        int _761 = (_751 + _393.x) + 1;
        int _766 = _751 + min((_393.x + 2), _387.x);
        float2 _776;
        if (_393.x == 0)
        {
            _776 = ((Grid_1._data[_757] * 3.0) - (Grid_1._data[_761] * 3.0)) + Grid_1._data[_766];
        }
        else
        {
            _776 = Grid_1._data[_751 + max((_393.x - 1), 0)];
        }
        float2 _785;
        if (_393.x == (_387.x - 1))
        {
            _785 = ((Grid_1._data[_761] * 3.0) - (Grid_1._data[_757] * 3.0)) + _776;
        }
        else
        {
            _785 = Grid_1._data[_766];
        }
        _399[1] = (((_776 * _403.x) + (Grid_1._data[_757] * _403.y)) + (Grid_1._data[_761] * _403.z)) + (_785 * _403.w);
        _403 = _609;
        int _821 = clamp(_393.y + 1, 0, _387.y) * (_387.x + 1);
        int _827 = _821 + _393.x;
        int _831 = (_821 + _393.x) + 1;
        int _836 = _821 + min((_393.x + 2), _387.x);
        float2 _846;
        if (_393.x == 0)
        {
            _846 = ((Grid_1._data[_827] * 3.0) - (Grid_1._data[_831] * 3.0)) + Grid_1._data[_836];
        }
        else
        {
            _846 = Grid_1._data[_821 + max((_393.x - 1), 0)];
        }
        float2 _855;
        if (_393.x == (_387.x - 1))
        {
            _855 = ((Grid_1._data[_831] * 3.0) - (Grid_1._data[_827] * 3.0)) + _846;
        }
        else
        {
            _855 = Grid_1._data[_836];
        }
        _399[2] = (((_846 * _403.x) + (Grid_1._data[_827] * _403.y)) + (Grid_1._data[_831] * _403.z)) + (_855 * _403.w);
        _403 = _609;
        int _891 = clamp(_393.y + 2, 0, _387.y) * (_387.x + 1);
        int _897 = _891 + _393.x;
        int _901 = (_891 + _393.x) + 1;
        int _906 = _891 + min((_393.x + 2), _387.x);
        float2 _916;
        if (_393.x == 0)
        {
            _916 = ((Grid_1._data[_897] * 3.0) - (Grid_1._data[_901] * 3.0)) + Grid_1._data[_906];
        }
        else
        {
            _916 = Grid_1._data[_891 + max((_393.x - 1), 0)];
        }
        float2 _925;
        if (_393.x == (_387.x - 1))
        {
            _925 = ((Grid_1._data[_901] * 3.0) - (Grid_1._data[_897] * 3.0)) + _916;
        }
        else
        {
            _925 = Grid_1._data[_906];
        }
        _399[3] = (((_916 * _403.x) + (Grid_1._data[_897] * _403.y)) + (Grid_1._data[_901] * _403.z)) + (_925 * _403.w);
        if (_393.y == 0)
        {
            _399[0] = ((_399[1] * 3.0) - (_399[2] * 3.0)) + _399[3];
        }
        if (_393.y == (_387.y - 1))
        {
            _399[3] = ((_399[2] * 3.0) - (_399[1] * 3.0)) + _399[0];
        }
        Precomputed.write(((((_399[0] * _396.x) + (_399[1] * _396.y)) + (_399[2] * _396.z)) + (_399[3] * _396.w)).xyyy, uint2(gl_GlobalInvocationID.xy));
        break;
    } while(false);
}

