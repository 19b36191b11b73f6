// The entry point of a permutation wrapper, CRLF line ends.
[numthreads(1, 1, 1)]
void main()
{
    Out[0] = Twice(In[0]) + SCALE * In[0];
}
