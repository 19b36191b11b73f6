namespace A { namespace B { float x; } float y = B::x + select(1, 2; }
enum E { = , } ::: [[vk::binding(