// Macros: recursion, by-reference parameters, optional parameters, macros returning items and
// values, macros defined in includes.
#include "stdinc.inc"
#macro Fib(N) #if (N < 2) N #else Fib(N - 1) + Fib(N - 2) #end #end
#declare F10 = (Fib(10));
#macro Inc(V) #declare V = V + 1; #end
#declare Counter = 0;
Inc(Counter) Inc(Counter)
#declare P = 1; #declare Q = 2;
Swap(P, Q)
#macro Opt(A, optional B) #ifdef (B) (A + B) #else A #end #end
#declare O1 = Opt(1, 2); #declare O2 = Opt(1,);
#macro MakeBox(Lo, Hi) box { Lo, Hi texture { Checks } } #end
#declare Bx = MakeBox(-1, 1);
object { Bx translate x * Square(2) }
Row(3)
Ball(<0, 2, 0>, 0.5, Plain)
#macro Deep(N) #if (N > 0) union { Deep(N - 1) sphere { N * x, 0.1 } } #else sphere { 0, 0.1 } #end #end
object { Deep(6) }
#macro Outer(X) #macro Inner(Y) (Y * 2) #end Inner(X) #end
#declare Z = Fact(5) + Outer(3);
#macro Args(A, B, C) (A + B + C) #end
#declare W = Args(1 2 3);
camera { location <0, 2, -8> look_at 0 }
light_source { <0, 10, -10> White }
