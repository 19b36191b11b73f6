// Common/Cube.fxh — cube and panorama geometry shared by the bake shaders.
#ifndef COMMON_CUBE_FXH
#define COMMON_CUBE_FXH

static const float CUBE_PI = 3.14159265358979323846f;

// The direction through a point of a cube face: uv in [0, 1]² across the face (v downwards),
// faces +X, -X, +Y, -Y, +Z, -Z. The same table as PrefilterSpecularCS (Direct3D's, which is
// also Vulkan's face selection), so every cube the kit writes is read back the same way.
// CubeFacePoint is the point itself, on the face of the cube [-1, 1]³.
float3 CubeFacePoint( uint face, float2 uv )
{
    uv = ( uv - 0.5f ) * float2( 2.f, -2.f );
    float3 direction;
    if ( face == 0 )      direction = float3( 1.f, uv.y, -uv.x );
    else if ( face == 1 ) direction = float3( -1.f, uv.y, uv.x );
    else if ( face == 2 ) direction = float3( uv.x, 1.f, -uv.y );
    else if ( face == 3 ) direction = float3( uv.x, -1.f, uv.y );
    else if ( face == 4 ) direction = float3( uv.x, uv.y, 1.f );
    else                  direction = float3( -uv.x, uv.y, -1.f );
    return direction;
}

float3 CubeFaceDirection( uint face, float2 uv )
{
    return normalize( CubeFacePoint( face, uv ) );
}

// Solid angle of texel (x, y) of a size x size face: the exact area of its projection on the
// unit sphere, from the integral of the face's area element (x y / sqrt(x² + y² + 1) form).
float CubeAreaElement( float x, float y )
{
    return atan2( x * y, sqrt( x * x + y * y + 1.f ) );
}

float CubeTexelSolidAngle( uint2 texel, uint size )
{
    float inverseSize = 1.f / size;
    float x0 = 2.f * texel.x * inverseSize - 1.f;
    float y0 = 2.f * texel.y * inverseSize - 1.f;
    float x1 = x0 + 2.f * inverseSize;
    float y1 = y0 + 2.f * inverseSize;
    return CubeAreaElement( x0, y0 ) - CubeAreaElement( x0, y1 ) - CubeAreaElement( x1, y0 ) + CubeAreaElement( x1, y1 );
}

// Equirectangular (latitude-longitude) panorama: u = 0.5 looks down -Z, u grows towards +X,
// v = 0 is straight up (+Y) and v = 1 straight down.
float2 DirectionToEquirect( float3 direction )
{
    float longitude = atan2( direction.x, -direction.z );
    float latitude = acos( clamp( direction.y, -1.f, 1.f ) );
    return float2( 0.5f + longitude / ( 2.f * CUBE_PI ), latitude / CUBE_PI );
}

float3 EquirectToDirection( float2 uv )
{
    float longitude = ( uv.x - 0.5f ) * 2.f * CUBE_PI;
    float latitude = uv.y * CUBE_PI;
    return float3( sin( latitude ) * sin( longitude ), cos( latitude ), -sin( latitude ) * cos( longitude ) );
}

#endif // COMMON_CUBE_FXH
