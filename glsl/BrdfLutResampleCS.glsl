#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std430) readonly buffer Grid
{
    vec2 _data[];
} Grid_1;

layout(binding = 0, std140) uniform LutGridParameter
{
    uint GridSize;
} _245;

layout(binding = 0, rg16f) uniform writeonly image2D Precomputed;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec2 _388 = uvec2(0u);
        uvec2 _389 = uvec2(imageSize(Precomputed));
        _388.x = _389.x;
        _388.y = _389.y;
        if (any(greaterThanEqual(gl_GlobalInvocationID.xy, _388)))
        {
            break;
        }
        ivec2 _435 = ivec2(int(_245.GridSize));
        ivec2 _390 = _435 - ivec2(1);
        float _445 = (float(param.x) + 0.5) / float(_388.x);
        vec2 _462 = vec2(pow(_445 / (1.0 + sqrt(1.0 - _445)), 0.3333333432674407958984375) * float(uint(_390.x)), pow((float(param.y) + 0.5) / float(_388.y), 0.3333333432674407958984375) * float(uint(_390.y)));
        vec2 _391 = _462;
        ivec2 _396 = min(ivec2(_462), (_435 - ivec2(2)));
        float _474 = _391.x - float(_396.x);
        float _555 = _474 * _474;
        float _558 = _555 * _474;
        vec4 _583 = vec4(fma(-_555, _474, fma(2.0, _555, -_474)), fma(3.0, _558, fma(-5.0, _555, 2.0)), fma(-3.0, _558, fma(4.0, _555, _474)), fma(_555, _474, -_555)) * 0.5;
        float _481 = _391.y - float(_396.y);
        float _590 = _481 * _481;
        float _593 = _590 * _481;
        int _632 = clamp(_396.y - 1, 0, _390.y) * (_390.x + 1);
        int _640 = _632 + _396.x;
        int _644 = (_632 + _396.x) + 1;
        int _650 = _632 + min((_396.x + 2), _390.x);
        vec4 _626 = _583;
        vec2 _758;
        if (_396.x == 0)
        {
            _758 = ((Grid_1._data[_640] * 3.0) - (Grid_1._data[_644] * 3.0)) + Grid_1._data[_650];
        }
        else
        {
            _758 = Grid_1._data[_632 + max((_396.x - 1), 0)];
        }
        vec2 _760;
        if (_396.x == (_390.x - 1))
        {
            _760 = ((Grid_1._data[_644] * 3.0) - (Grid_1._data[_640] * 3.0)) + _758;
        }
        else
        {
            _760 = Grid_1._data[_650];
        }
        vec2 _402[4];
        _402[0] = (((_758 * _626.x) + (Grid_1._data[_640] * _626.y)) + (Grid_1._data[_644] * _626.z)) + (_760 * _626.w);
        int _785 = clamp(_396.y, 0, _390.y) * (_390.x + 1);
        int _789 = _785 + _396.x;
        int _791 = (_785 + _396.x) + 1;
        int _794 = _785 + min((_396.x + 2), _390.x);
        _626 = _583;
        vec2 _810;
        if (_396.x == 0)
        {
            _810 = ((Grid_1._data[_789] * 3.0) - (Grid_1._data[_791] * 3.0)) + Grid_1._data[_794];
        }
        else
        {
            _810 = Grid_1._data[_785 + max((_396.x - 1), 0)];
        }
        vec2 _819;
        if (_396.x == (_390.x - 1))
        {
            _819 = ((Grid_1._data[_791] * 3.0) - (Grid_1._data[_789] * 3.0)) + _810;
        }
        else
        {
            _819 = Grid_1._data[_794];
        }
        _402[1] = (((_810 * _626.x) + (Grid_1._data[_789] * _626.y)) + (Grid_1._data[_791] * _626.z)) + (_819 * _626.w);
        int _855 = clamp(_396.y + 1, 0, _390.y) * (_390.x + 1);
        int _859 = _855 + _396.x;
        int _861 = (_855 + _396.x) + 1;
        int _864 = _855 + min((_396.x + 2), _390.x);
        _626 = _583;
        vec2 _880;
        if (_396.x == 0)
        {
            _880 = ((Grid_1._data[_859] * 3.0) - (Grid_1._data[_861] * 3.0)) + Grid_1._data[_864];
        }
        else
        {
            _880 = Grid_1._data[_855 + max((_396.x - 1), 0)];
        }
        vec2 _889;
        if (_396.x == (_390.x - 1))
        {
            _889 = ((Grid_1._data[_861] * 3.0) - (Grid_1._data[_859] * 3.0)) + _880;
        }
        else
        {
            _889 = Grid_1._data[_864];
        }
        _402[2] = (((_880 * _626.x) + (Grid_1._data[_859] * _626.y)) + (Grid_1._data[_861] * _626.z)) + (_889 * _626.w);
        int _925 = clamp(_396.y + 2, 0, _390.y) * (_390.x + 1);
        int _929 = _925 + _396.x;
        int _931 = (_925 + _396.x) + 1;
        int _934 = _925 + min((_396.x + 2), _390.x);
        _626 = _583;
        vec2 _950;
        if (_396.x == 0)
        {
            _950 = ((Grid_1._data[_929] * 3.0) - (Grid_1._data[_931] * 3.0)) + Grid_1._data[_934];
        }
        else
        {
            _950 = Grid_1._data[_925 + max((_396.x - 1), 0)];
        }
        vec2 _959;
        if (_396.x == (_390.x - 1))
        {
            _959 = ((Grid_1._data[_931] * 3.0) - (Grid_1._data[_929] * 3.0)) + _950;
        }
        else
        {
            _959 = Grid_1._data[_934];
        }
        _402[3] = (((_950 * _626.x) + (Grid_1._data[_929] * _626.y)) + (Grid_1._data[_931] * _626.z)) + (_959 * _626.w);
        vec4 _414 = vec4(fma(-_590, _481, fma(2.0, _590, -_481)), fma(3.0, _593, fma(-5.0, _590, 2.0)), fma(-3.0, _593, fma(4.0, _590, _481)), fma(_590, _481, -_590)) * 0.5;
        vec2 _754;
        if (_396.y == 0)
        {
            _754 = ((_402[1] * 3.0) - (_402[2] * 3.0)) + _402[3];
        }
        else
        {
            _754 = _402[0];
        }
        vec2 _756;
        if (_396.y == (_390.y - 1))
        {
            _756 = ((_402[2] * 3.0) - (_402[1] * 3.0)) + _754;
        }
        else
        {
            _756 = _402[3];
        }
        imageStore(Precomputed, ivec2(gl_GlobalInvocationID.xy), clamp((((_754 * _414.x) + (_402[1] * _414.y)) + (_402[2] * _414.z)) + (_756 * _414.w), vec2(0.0), vec2(1.0)).xyyy);
        break;
    } while(false);
}

