// Directives: #declare/#local/#undef, conditionals, loops, #switch fall-through, #version,
// #default, messages.
#version 3.7;
#declare A = 1;
#local B = <1, 2, 3>;
#declare C = rgbft <0.1, 0.2, 0.3, 0.4, 0.5>;
#undef A
#ifdef (A) #error "A is undefined" #end
#ifndef (A) #declare A = 2; #end
#if (A = 2 & B.y > 1) #debug "both\n" #elseif (A) #debug "A\n" #else #debug "none\n" #end
#switch (A)
  #case (1) #debug "one\n"
  #case (2) #debug "two\n"          // falls through
  #range (3, 5) #debug "three to five\n" #break
  #else #debug "other\n"
#end
#declare I = 0;
#while (I < 5) #declare I = I + 1; #if (I = 3) #break #end #end
#for (J, 10, 0, -2.5) #debug concat(str(J, 0, 1), " ") #end
#for (K, 0, 1, 0.25) #end
#default { finish { ambient 0.2 diffuse 0.6 } }
#default { pigment { rgb 0.5 } }
#warning "a warning"
#statistics "stats\n"
#render "render\n"
#if (version >= 3.5) #declare V = version; #end
#declare D = (A > 1 ? 3 : 4) + mod(7, 3) - div(7, 2) * pow(2, 3) / (1 + abs(-2));
#declare E = ((A != 2) | ((A <= 2) & (A >= 1))) + !A;
#declare T = true; #declare F = off; #declare Y = yes;
camera { location <0, 1, -5> look_at 0 }
light_source { <5, 5, -5> color rgb 1 }
sphere { 0, 1 pigment { color rgb <1, 0, 0> } }
