// An interface and a class that implements it.
interface IShape { float area(); };
class Square : IShape { float side; float area() { return side * side; } };
RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main() { Square square; square.side = 2; Out[0] = square.area(); }
