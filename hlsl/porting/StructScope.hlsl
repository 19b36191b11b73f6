// A struct's static members with their values, its enums and its static member functions, as
// C++-minded engine headers write them: used inside the struct (an array's size, a member
// function) and outside as S::Name.
struct Feedback
{
    const static int MaxItems = 2 * 2;
    enum Types { Type_Line = 0, Type_Circle = 1 };
    float Items[MaxItems];
    int Kind;
    bool IsLine() { return Kind == Type_Line; }
    static Feedback Make(int kind) { Feedback made = (Feedback)0; made.Kind = kind; return made; }
};
StructuredBuffer<int> In : register(t0);
RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    Feedback feedback = Feedback::Make(In[0]);
    feedback.Items[Feedback::MaxItems - 1] = 7.0;
    Out[0] = Feedback::MaxItems;
    Out[1] = feedback.IsLine() ? 10.0 : 20.0;
    Out[2] = feedback.Kind == Feedback::Type_Circle ? feedback.Items[3] : -1.0;
}
