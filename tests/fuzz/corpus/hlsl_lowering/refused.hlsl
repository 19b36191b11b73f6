template <typename T> T twice(T x) { return x * 2; }
struct S { uint a : 4; uint b : 28; };
S operator+(S a, S b);
