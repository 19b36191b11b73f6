// Common/SphericalHarmonics.fxh — the real spherical harmonics of bands 0 to 2.
#ifndef COMMON_SPHERICAL_HARMONICS_FXH
#define COMMON_SPHERICAL_HARMONICS_FXH

static const uint SH_COEFFICIENT_COUNT = 9;

// Y_lm(direction) for (l, m) = (0,0), (1,-1), (1,0), (1,1), (2,-2), (2,-1), (2,0), (2,1), (2,2),
// with z as the polar axis (Ramamoorthi and Hanrahan, "An Efficient Representation for
// Irradiance Environment Maps", 2001, equation 3).
void ShBasis( float3 d, out float basis[SH_COEFFICIENT_COUNT] )
{
    basis[0] = 0.282094791773878f;
    basis[1] = 0.488602511902920f * d.y;
    basis[2] = 0.488602511902920f * d.z;
    basis[3] = 0.488602511902920f * d.x;
    basis[4] = 1.092548430592079f * d.x * d.y;
    basis[5] = 1.092548430592079f * d.y * d.z;
    basis[6] = 0.315391565252520f * ( 3.f * d.z * d.z - 1.f );
    basis[7] = 1.092548430592079f * d.x * d.z;
    basis[8] = 0.546274215296040f * ( d.x * d.x - d.y * d.y );
}

#endif // COMMON_SPHERICAL_HARMONICS_FXH
