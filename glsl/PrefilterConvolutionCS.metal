#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct PrefilterConvolutionParameter
{
    float Roughness;
    uint TopLevel;
    uint FineLevel;
    float Refine;
    uint HorizonLevel;
};

kernel void main0(constant PrefilterConvolutionParameter& _378 [[buffer(0)]], texture2d_array<float> Energy [[texture(0)]], texture2d_array<float> Centroid [[texture(1)]], texture2d_array<float> Geometry [[texture(2)]], texture2d_array<float, access::write> Prefiltered [[texture(3)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _736 = uint3(0u);
        uint3 _737 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _736.x = _737.x;
        _736.y = _737.y;
        _736.z = _737.z;
        if (any(gl_GlobalInvocationID >= _736))
        {
            break;
        }
        float2 _740 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(float(_736.x))) - float2(0.5)) * float2(2.0, -2.0);
        float3 _1612;
        if (param.z == 0u)
        {
            _1612 = float3(1.0, _740.y, -_740.x);
        }
        else
        {
            float3 _1613;
            if (param.z == 1u)
            {
                _1613 = float3(-1.0, _740.y, _740.x);
            }
            else
            {
                float3 _1614;
                if (param.z == 2u)
                {
                    _1614 = float3(_740.x, 1.0, -_740.y);
                }
                else
                {
                    float3 _1615;
                    if (param.z == 3u)
                    {
                        _1615 = float3(_740.x, -1.0, _740.y);
                    }
                    else
                    {
                        float3 _1616;
                        if (param.z == 4u)
                        {
                            _1616 = float3(_740.x, _740.y, 1.0);
                        }
                        else
                        {
                            _1616 = float3(-_740.x, _740.y, -1.0);
                        }
                        _1615 = _1616;
                    }
                    _1614 = _1615;
                }
                _1613 = _1614;
            }
            _1612 = _1613;
        }
        float3 _1005 = fast::normalize(_1612);
        uint3 _745 = uint3(Energy.get_width(0u), Energy.get_height(0u), Energy.get_array_size());
        uint _820 = max((_745.x >> _378.TopLevel), 1u);
        float3 _1618;
        float _1619;
        uint2 _1624;
        _1624 = uint2(0u);
        _1619 = 0.0;
        _1618 = float3(0.0);
        float3 _906;
        float _916;
        uint2 _923;
        uint _1679;
        uint _1681;
        for (uint _1617 = 0u, _1621 = _378.TopLevel; _1617 < 6u; _1624 = _923, _1621 = _1679, _1619 = _916, _1618 = _906, _1617 = _1681)
        {
            uint _1620;
            uint2 _1623;
            _1623 = _1624;
            _1620 = _1621;
            uint2 _847;
            uint _849;
            for (;;)
            {
                uint _837 = max((_745.x >> _1620), 1u);
                float2 _1008 = (((float2(_1623) + float2(0.5)) / float2(float(_837))) - float2(0.5)) * float2(2.0, -2.0);
                float3 _1625;
                if (_1617 == 0u)
                {
                    _1625 = float3(1.0, _1008.y, -_1008.x);
                }
                else
                {
                    float3 _1626;
                    if (_1617 == 1u)
                    {
                        _1626 = float3(-1.0, _1008.y, _1008.x);
                    }
                    else
                    {
                        float3 _1627;
                        if (_1617 == 2u)
                        {
                            _1627 = float3(_1008.x, 1.0, -_1008.y);
                        }
                        else
                        {
                            float3 _1628;
                            if (_1617 == 3u)
                            {
                                _1628 = float3(_1008.x, -1.0, _1008.y);
                            }
                            else
                            {
                                float3 _1629;
                                if (_1617 == 4u)
                                {
                                    _1629 = float3(_1008.x, _1008.y, 1.0);
                                }
                                else
                                {
                                    _1629 = float3(-_1008.x, _1008.y, -1.0);
                                }
                                _1628 = _1629;
                            }
                            _1627 = _1628;
                        }
                        _1626 = _1627;
                    }
                    _1625 = _1626;
                }
                float _1027 = dot(_1005, fast::normalize(_1625));
                float _1033 = (_378.Refine * 2.0) / float(_837);
                if ((_1620 > _378.FineLevel) && ((fma(-2.0, _1027, 2.0) < (_1033 * _1033)) || ((_1620 > _378.HorizonLevel) && (abs(_1027) < (2.0 / float(_837))))))
                {
                    _847 = _1623 * uint2(2u);
                    _849 = _1620 - 1u;
                    _1623 = _847;
                    _1620 = _849;
                    continue;
                }
                else
                {
                    break;
                }
            }
            int4 _860 = int4(int2(_1623), int(_1617), int(_1620));
            int4 _757 = _860;
            int3 _863 = _860.xyz;
            float4 _866 = Energy.read(uint2(_863.xy), uint(_863.z), _757.w);
            float4 _758 = _866;
            int3 _869 = _860.xyz;
            float4 _872 = Centroid.read(uint2(_869.xy), uint(_869.z), _757.w);
            float4 _759 = _872;
            int3 _875 = _860.xyz;
            float4 _878 = Geometry.read(uint2(_875.xy), uint(_875.z), _757.w);
            float4 _760 = _878;
            float3 _884 = _878.xyz / float3(_760.w);
            float3 _896 = select(_884, _872.xyz / float3(_759.w), bool3(_759.w > 0.0));
            float _1132 = dot(_896, _896);
            float _1135 = dot(_1005, _896);
            float _1147 = (0.5 * fast::max(1.0 - _1132, 0.0)) * fast::max(1.0 - ((_1135 * _1135) / _1132), 0.0);
            float _1167 = sqrt(fast::max(_1147, 0.0));
            float _1172 = sqrt(fma(0.5, fast::max(_1135, 0.0), 0.5));
            float _1235 = _378.Roughness * _378.Roughness;
            float _1247 = fma(_1172 * _1172, fma(_1235, _1235, -1.0), 1.0);
            float _1646;
            if (_1135 > (3.0 * _1167))
            {
                float _1186 = ((_378.Roughness * _378.Roughness) * _378.Roughness) * _378.Roughness;
                float _1189 = fma(0.5, _1186, 0.5);
                float _1192 = fma(0.5, _1186, -0.5);
                float _1197 = fma(_1192, _1135, _1189);
                _1646 = _1135 + ((((0.5 * _1147) * (-_1192)) * fma(4.0, _1189, -((2.0 * _1192) * _1135))) / (_1197 * _1197));
            }
            else
            {
                float _1645;
                if ((_1167 > 0.0) && (abs(_1135) <= (5.0 * _1167)))
                {
                    float _1274 = _1135 / _1167;
                    float _1298 = abs(_1274);
                    float _1302 = fma(_1298, 0.23164187371730804443359375, 1.0);
                    float _1303 = 1.0 / _1302;
                    float _1319 = (0.5 / _1302) * fma(_1303, fma(_1303, fma(_1303, (-1.45315206050872802734375) + (1.0614054203033447265625 / _1302), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _1324 = exp((_1298 * (-0.707106769084930419921875)) * (_1298 * 0.707106769084930419921875));
                    _1645 = fma(_1167, exp(((-0.5) * _1274) * _1274) * 0.398942291736602783203125, _1135 * ((_1274 >= 0.0) ? fma(-_1319, _1324, 1.0) : (_1319 * _1324)));
                }
                else
                {
                    _1645 = fast::max(_1135, 0.0);
                }
                _1646 = fast::max(_1645, 0.0);
            }
            _906 = _1618 + (_866.xyz * (((_1235 * _1235) / ((3.1415927410125732421875 * _1247) * _1247)) * _1646));
            float _1342 = dot(_884, _884);
            float _1345 = dot(_1005, _884);
            float _1357 = (0.5 * fast::max(1.0 - _1342, 0.0)) * fast::max(1.0 - ((_1345 * _1345) / _1342), 0.0);
            float _1377 = sqrt(fast::max(_1357, 0.0));
            float _1382 = sqrt(fma(0.5, fast::max(_1345, 0.0), 0.5));
            float _1445 = _378.Roughness * _378.Roughness;
            float _1457 = fma(_1382 * _1382, fma(_1445, _1445, -1.0), 1.0);
            float _1656;
            if (_1345 > (3.0 * _1377))
            {
                float _1396 = ((_378.Roughness * _378.Roughness) * _378.Roughness) * _378.Roughness;
                float _1399 = fma(0.5, _1396, 0.5);
                float _1402 = fma(0.5, _1396, -0.5);
                float _1407 = fma(_1402, _1345, _1399);
                _1656 = _1345 + ((((0.5 * _1357) * (-_1402)) * fma(4.0, _1399, -((2.0 * _1402) * _1345))) / (_1407 * _1407));
            }
            else
            {
                float _1655;
                if ((_1377 > 0.0) && (abs(_1345) <= (5.0 * _1377)))
                {
                    float _1484 = _1345 / _1377;
                    float _1508 = abs(_1484);
                    float _1512 = fma(_1508, 0.23164187371730804443359375, 1.0);
                    float _1513 = 1.0 / _1512;
                    float _1529 = (0.5 / _1512) * fma(_1513, fma(_1513, fma(_1513, (-1.45315206050872802734375) + (1.0614054203033447265625 / _1512), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _1534 = exp((_1508 * (-0.707106769084930419921875)) * (_1508 * 0.707106769084930419921875));
                    _1655 = fma(_1377, exp(((-0.5) * _1484) * _1484) * 0.398942291736602783203125, _1345 * ((_1484 >= 0.0) ? fma(-_1529, _1534, 1.0) : (_1529 * _1534)));
                }
                else
                {
                    _1655 = fast::max(_1345, 0.0);
                }
                _1656 = fast::max(_1655, 0.0);
            }
            _916 = fma(_758.w, ((_1445 * _1445) / ((3.1415927410125732421875 * _1457) * _1457)) * _1656, _1619);
            uint2 _770 = _1623;
            _1679 = _1620;
            uint _1563;
            for (; (_1679 < _378.TopLevel) && (((_770.x & _770.y) & 1u) != 0u); _1679 = _1563)
            {
                _770 = _770 >> uint2(int2(1));
                _1563 = _1679 + 1u;
            }
            if (_1679 == _378.TopLevel)
            {
                uint _1575 = _770.y;
                uint _1580 = _770.x;
                uint _1582 = ((((_1617 * _820) + _1575) * _820) + _1580) + 1u;
                _770 = uint2(_1582 % _820, (_1582 / _820) % _820);
                _1681 = _1582 / (_820 * _820);
            }
            else
            {
                if ((_770.x & 1u) == 0u)
                {
                    _770.x++;
                }
                else
                {
                    _770 += uint2(4294967295u, 1u);
                }
                _1681 = _1617;
            }
            _923 = _770;
        }
        Prefiltered.write(float4(_1618 / float3(_1619), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

