#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std430) readonly buffer Grid
{
    vec2 _data[];
} Grid_1;

layout(binding = 0, std140) uniform LutGridParameter
{
    uint GridSize;
} _228;

layout(binding = 0, rg16f) uniform writeonly image2D Precomputed;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec2 _367 = uvec2(0u);
        uvec2 _368 = uvec2(imageSize(Precomputed));
        _367.x = _368.x;
        _367.y = _368.y;
        if (any(greaterThanEqual(gl_GlobalInvocationID.xy, _367)))
        {
            break;
        }
        ivec2 _414 = ivec2(int(_228.GridSize));
        ivec2 _369 = _414 - ivec2(1);
        vec2 _441 = vec2(pow((float(param.x) + 0.5) / float(_367.x), 0.3333333432674407958984375) * float(uint(_369.x)), pow((float(param.y) + 0.5) / float(_367.y), 0.3333333432674407958984375) * float(uint(_369.y)));
        vec2 _370 = _441;
        ivec2 _375 = min(ivec2(_441), (_414 - ivec2(2)));
        float _453 = _370.x - float(_375.x);
        float _526 = _453 * _453;
        float _529 = _526 * _453;
        vec4 _554 = vec4(fma(-_526, _453, fma(2.0, _526, -_453)), fma(3.0, _529, fma(-5.0, _526, 2.0)), fma(-3.0, _529, fma(4.0, _526, _453)), fma(_526, _453, -_526)) * 0.5;
        float _460 = _370.y - float(_375.y);
        float _561 = _460 * _460;
        float _564 = _561 * _460;
        int _603 = clamp(_375.y - 1, 0, _369.y) * (_369.x + 1);
        int _611 = _603 + _375.x;
        int _615 = (_603 + _375.x) + 1;
        int _621 = _603 + min((_375.x + 2), _369.x);
        vec4 _597 = _554;
        vec2 _729;
        if (_375.x == 0)
        {
            _729 = ((Grid_1._data[_611] * 3.0) - (Grid_1._data[_615] * 3.0)) + Grid_1._data[_621];
        }
        else
        {
            _729 = Grid_1._data[_603 + max((_375.x - 1), 0)];
        }
        vec2 _731;
        if (_375.x == (_369.x - 1))
        {
            _731 = ((Grid_1._data[_615] * 3.0) - (Grid_1._data[_611] * 3.0)) + _729;
        }
        else
        {
            _731 = Grid_1._data[_621];
        }
        vec2 _381[4];
        _381[0] = (((_729 * _597.x) + (Grid_1._data[_611] * _597.y)) + (Grid_1._data[_615] * _597.z)) + (_731 * _597.w);
        int _754 = clamp(_375.y, 0, _369.y) * (_369.x + 1);
        int _758 = _754 + _375.x;
        int _760 = (_754 + _375.x) + 1;
        int _763 = _754 + min((_375.x + 2), _369.x);
        _597 = _554;
        vec2 _779;
        if (_375.x == 0)
        {
            _779 = ((Grid_1._data[_758] * 3.0) - (Grid_1._data[_760] * 3.0)) + Grid_1._data[_763];
        }
        else
        {
            _779 = Grid_1._data[_754 + max((_375.x - 1), 0)];
        }
        vec2 _788;
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
        vec2 _849;
        if (_375.x == 0)
        {
            _849 = ((Grid_1._data[_828] * 3.0) - (Grid_1._data[_830] * 3.0)) + Grid_1._data[_833];
        }
        else
        {
            _849 = Grid_1._data[_824 + max((_375.x - 1), 0)];
        }
        vec2 _858;
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
        vec2 _919;
        if (_375.x == 0)
        {
            _919 = ((Grid_1._data[_898] * 3.0) - (Grid_1._data[_900] * 3.0)) + Grid_1._data[_903];
        }
        else
        {
            _919 = Grid_1._data[_894 + max((_375.x - 1), 0)];
        }
        vec2 _928;
        if (_375.x == (_369.x - 1))
        {
            _928 = ((Grid_1._data[_900] * 3.0) - (Grid_1._data[_898] * 3.0)) + _919;
        }
        else
        {
            _928 = Grid_1._data[_903];
        }
        _381[3] = (((_919 * _597.x) + (Grid_1._data[_898] * _597.y)) + (Grid_1._data[_900] * _597.z)) + (_928 * _597.w);
        vec4 _393 = vec4(fma(-_561, _460, fma(2.0, _561, -_460)), fma(3.0, _564, fma(-5.0, _561, 2.0)), fma(-3.0, _564, fma(4.0, _561, _460)), fma(_561, _460, -_561)) * 0.5;
        vec2 _725;
        if (_375.y == 0)
        {
            _725 = ((_381[1] * 3.0) - (_381[2] * 3.0)) + _381[3];
        }
        else
        {
            _725 = _381[0];
        }
        vec2 _727;
        if (_375.y == (_369.y - 1))
        {
            _727 = ((_381[2] * 3.0) - (_381[1] * 3.0)) + _725;
        }
        else
        {
            _727 = _381[3];
        }
        imageStore(Precomputed, ivec2(gl_GlobalInvocationID.xy), ((((_725 * _393.x) + (_381[1] * _393.y)) + (_381[2] * _393.z)) + (_727 * _393.w)).xyyy);
        break;
    } while(false);
}

