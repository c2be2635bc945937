/* comments /* nested */ */ // line comment
#declare A=1;#declare B=.5e+1;#declare C=1E-2;
#declare S="\u00e9\\\"\a\b\f\n\r\t\v";
#declare D = 010;
;;;
#
sphere{<A,B,C>,1}
#declare E = <1 2 3>;
#declare F = <1, 2, 3,>;
default { pigment { rgb 1 } }
