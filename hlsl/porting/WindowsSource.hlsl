// A shader saved as Visual Studio saves it: a UTF-8 byte-order mark and CRLF line ends, with
// includes written for a file system that ignores case and takes backslashes; its last line, an
// include with no newline after it, brings the entry point, as engines' permutation wrappers do.
StructuredBuffer<float> In : register(t0);
RWStructuredBuffer<float> Out : register(u0);

#include "include\\windowsheader.HLSLI"
#define SCALE 3.0
#include "Include/WindowsEntry.hlsli"