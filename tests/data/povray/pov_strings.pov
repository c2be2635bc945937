// Measures POV-Ray 3.7's string functions for tests/pov_strings_test.cpp.
// Run in this folder:  povray +Ipov_strings.pov +W1 +H1 -D -F   (writes pov_strings.txt)
// Cases that stop POV-Ray with an error are measured one by one by pov_string_errors.sh.
//
// Each output line is FUNCTION|ARGUMENTS...|RESULT, fields separated by '|'. Numbers are given as
// text and turned into floats with val() (C's strtod), so the line holds the exact input; a vector
// is its components joined by ';'. Codes above 127 are written as spaces by #write, so results
// with such codes are written as numbers (asc, strlen, strcmp).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location -z look_at 0 }
sphere { 0, 1 }

#fopen F "pov_strings.txt" write

#macro Str(V, L, P)
  #write(F, "str|", V, "|", L, "|", P, "|", str(val(V), val(L), val(P)), "\n")
#end
#macro Vec(C, X, Y, Z, T, U)
  #switch (C)
    #case (1) val(X) #break
    #case (2) <val(X), val(Y)> #break
    #case (3) <val(X), val(Y), val(Z)> #break
    #case (4) <val(X), val(Y), val(Z), val(T)> #break
    #case (5) <val(X), val(Y), val(Z), val(T), val(U)> #break
  #end
#end
#macro VecText(C, X, Y, Z, T, U)
  #local Parts = array[5] { X, Y, Z, T, U }
  #local S = Parts[0];
  #local I = 1;
  #while (I < C) #local S = concat(S, ";", Parts[I]); #local I = I + 1; #end
  S
#end
#macro Vstr(N, C, X, Y, Z, T, U, Sep, L, P)
  #write(F, "vstr|", N, "|", VecText(C, X, Y, Z, T, U), "|", Sep, "|", L, "|", P, "|",
         vstr(val(N), Vec(C, X, Y, Z, T, U), Sep, val(L), val(P)), "\n")
#end
#macro Val(S)      #write(F, "val|", S, "|", str(val(S), 0, 20), "\n") #end
#macro Write(V)    #write(F, "write|", V, "|", val(V), "\n") #end
#macro WriteVec(C, X, Y, Z, T, U)
  #write(F, "writevec|", VecText(C, X, Y, Z, T, U), "|", Vec(C, X, Y, Z, T, U), "\n")
#end
#macro Chr(C)      #local R = chr(val(C)); #write(F, "chr|", C, "|", str(strlen(R), 0, 0), ";", str(asc(R), 0, 0), "\n") #end
#macro Asc(S)      #write(F, "asc|", S, "|", str(asc(S), 0, 0), "\n") #end
#macro Strlen(S)   #write(F, "strlen|", S, "|", str(strlen(S), 0, 0), "\n") #end
#macro Upr(S)      #write(F, "strupr|", S, "|", strupr(S), "\n") #end
#macro Lwr(S)      #write(F, "strlwr|", S, "|", strlwr(S), "\n") #end
#macro UprCode(C)  #write(F, "struprcode|", C, "|", str(asc(strupr(chr(val(C)))), 0, 0), "\n") #end
#macro LwrCode(C)  #write(F, "strlwrcode|", C, "|", str(asc(strlwr(chr(val(C)))), 0, 0), "\n") #end
#macro Substr(S, P, L) #write(F, "substr|", S, "|", P, "|", L, "|", substr(S, val(P), val(L)), "\n") #end
#macro Strcmp(A, B) #write(F, "strcmp|", A, "|", B, "|", str(strcmp(A, B), 0, 0), "\n") #end
#macro Datetime(D, Fmt) #write(F, "datetime|", D, "|", Fmt, "|", datetime(val(D), Fmt), "\n") #end
#macro DatetimeDefault(D) #write(F, "datetime|", D, "|(default)|", datetime(val(D)), "\n") #end

// ---- str(A, L, P) --------------------------------------------------------------------------------
Str("123.456", "0", "3") Str("123.456", "4", "3") Str("123.456", "9", "3") Str("123.456", "-9", "3")
Str("123.456", "0", "2") Str("123.456", "0", "0") Str("123.456", "5", "0") Str("123", "7", "2")
Str("123.456", "0", "-1") Str("123.456", "0", "-5") Str("123.456", "0", "254")
Str("-123.456", "9", "3") Str("-123.456", "-9", "3") Str("-123.456", "0", "0")
Str("0", "0", "0") Str("0", "-5", "0") Str("0", "0", "3")
Str("-0", "0", "3") Str("-0", "0", "0") Str("-0", "-6", "2") Str("-0", "6", "2")
Str("-0.0001", "0", "2") Str("-0.0001", "0", "0") Str("-0.4", "0", "0")
Str("0.5", "0", "0") Str("1.5", "0", "0") Str("2.5", "0", "0") Str("3.5", "0", "0")
Str("0.125", "0", "2") Str("0.375", "0", "2") Str("1.005", "0", "2")
Str("1.5", "5.9", "2.9") Str("1.5", "-5.9", "2.9") Str("1.5", "5", "-0.5") Str("1.5", "5", "-0.9")
Str("1.5", "1e10", "2") Str("1.5", "0", "1e10") Str("1.5", "-1e10", "2")
Str("1", "254", "0") Str("1", "255", "0") Str("1", "-254", "0") Str("1", "-255", "0")
Str("1", "250", "254") Str("1", "-250", "254")
Str("1", "0", "16") Str("1", "0", "17") Str("1", "0", "20") Str("1", "0", "30")
Str("1", "0", "252") Str("1", "0", "253") Str("1", "0", "1000") Str("1", "0", "100000000")
Str("0.3333333333333333", "0", "16") Str("0.3333333333333333", "0", "17")
Str("0.3333333333333333", "0", "18") Str("0.3333333333333333", "0", "30")
Str("1e15", "0", "3") Str("1e16", "0", "3") Str("1e17", "0", "3") Str("1e20", "0", "3")
Str("1e22", "0", "3") Str("1e25", "0", "3") Str("123456789012345678", "0", "3")
Str("1e100", "0", "3") Str("1e100", "0", "0") Str("1e100", "0", "10")
Str("1e250", "0", "3") Str("1e250", "0", "4") Str("1e250", "0", "-1")
Str("1e254", "0", "0") Str("1e255", "0", "0") Str("-1e253", "0", "0") Str("-1e254", "0", "0")
Str("1e300", "0", "3") Str("1e300", "0", "0") Str("1e300", "0", "-1") Str("1e300", "10", "2")
Str("1e300", "-10", "2") Str("1e300", "255", "2") Str("1.23456789e300", "0", "-1")
Str("-1e300", "0", "3") Str("1e308", "0", "3") Str("1.7976931348623157e308", "0", "2")
Str("1e-5", "0", "3") Str("1e-5", "0", "10") Str("1e-20", "0", "30") Str("1e-300", "0", "3")
Str("4.9e-324", "0", "-1") Str("1e-7", "-12", "8")
Str("inf", "0", "2") Str("inf", "-8", "2") Str("inf", "8", "2") Str("-inf", "0", "2")
Str("nan", "0", "2") Str("-nan", "0", "2") Str("nan", "-6", "0")
Str("12", "0", "2") Str("12", "3", "2") Str("12", "6", "2") Str("12", "-6", "2")
Str("-12", "-6", "2") Str("-12", "-6", "-1") Str("-12", "-1", "2") Str("123456789", "0", "-1")
Str("-1.5", "-8", "2") Str("-1.5", "8", "2")

// ---- vstr(N, A, S, L, P) -------------------------------------------------------------------------
Vstr("2", 2, "1", "2", "", "", "", ", ", "0", "1")
Vstr("5", 5, "1", "2", "3", "4", "5", ", ", "0", "1")
Vstr("1", 1, "1", "", "", "", "", ", ", "0", "1")
Vstr("2", 1, "1", "", "", "", "", ", ", "0", "1")
Vstr("5", 1, "1", "", "", "", "", ", ", "0", "1")
Vstr("7", 1, "1", "", "", "", "", ", ", "0", "1")
Vstr("3", 1, "2.5", "", "", "", "", "/", "0", "1")
Vstr("3", 2, "1", "2", "", "", "", ", ", "0", "1")
Vstr("5", 3, "1", "2", "3", "", "", ", ", "0", "1")
Vstr("2", 3, "1", "2", "3", "", "", ",", "0", "1")
Vstr("3", 4, "1", "2", "3", "4", "", ",", "0", "1")
Vstr("4", 5, "1", "2", "3", "4", "5", ",", "0", "1")
Vstr("2.9", 3, "1", "2", "3", "", "", ",", "0", "1")
Vstr("-3", 3, "1", "2", "3", "", "", ",", "0", "1")
Vstr("0", 1, "1", "", "", "", "", ",", "0", "1")
Vstr("1e10", 3, "1", "2", "3", "", "", ",", "0", "1")
Vstr("3", 3, "1", "2", "3", "", "", "", "0", "1")
Vstr("3", 3, "1", "2", "3", "", "", "abcdefghij", "0", "1")
Vstr("3", 3, "1", "2", "3", "", "", ",", "5", "2")
Vstr("3", 3, "1", "2", "3", "", "", ",", "-5", "2")
Vstr("3", 3, "1", "-2", "3", "", "", ",", "-5", "-1")
Vstr("3", 3, "1", "2", "3", "", "", ",", "0", "0")
Vstr("3", 3, "-0", "2", "3", "", "", ",", "0", "1")
Vstr("3", 3, "1e300", "2", "3", "", "", ",", "0", "0")
Vstr("3", 3, "1e300", "2", "3", "", "", ",", "0", "6")
Vstr("3", 3, "1", "2", "3", "", "", ",", "0", "300")
Vstr("3", 3, "1", "2", "3", "", "", ",", "255", "2")
Vstr("2", 2, "1", "2", "", "", "", ",", "1e10", "1")
Vstr("2", 2, "1", "2", "", "", "", ",", "0", "1e10")
Vstr("2", 2, "inf", "-inf", "", "", "", ",", "-8", "1")
Vstr("2", 2, "nan", "-nan", "", "", "", ",", "0", "1")
Vstr("2", 2, "1", "2", "", "", "", ",", "0", "765")
Vstr("2", 2, "1", "2", "", "", "", ",", "767", "1")
Vstr("2", 2, "1", "2", "", "", "", ",", "-767", "1")
Vstr("2", 2, "1e308", "2", "", "", "", ",", "0", "400")

// ---- val(S) --------------------------------------------------------------------------------------
Val("123.45") Val("1e3") Val(" 2") Val("abc") Val("3x") Val("") Val("  ") Val("+5") Val("-5")
Val(".5") Val("5.") Val("0x10") Val("0X1A") Val("0x1p3") Val("0x") Val("0xg") Val("inf") Val("-inf")
Val("INF") Val("infinity") Val("infx") Val("inx") Val("nan") Val("NAN") Val("nan(123)") Val("1e")
Val("1e+") Val("1E2") Val("1,5") Val("\t7") Val("\v5") Val("\f5") Val("\r5") Val("7 ") Val("1e400")
Val("-1e400") Val("1e-400") Val("1e-310") Val("1.5e3.2") Val("--1") Val("- 1") Val("0012")
Val("1_000") Val("  -0") Val("-0") Val(".") Val("e5") Val("1d5") Val("4.9e-324") Val("0.1")
Val("2.2250738585072011e-308") Val("123456789012345678901234567890")
Val("1.0000000000000000000000000000000000000000000000001")
#write(F, "valcodes|200;53|", str(val(concat(chr(200), "5")), 0, 3), "\n")
#write(F, "valcodes|960;53|", str(val(concat(chr(960), "5")), 0, 3), "\n")
#write(F, "valcodes|49;960;50|", str(val(concat("1", chr(960), "2")), 0, 3), "\n")
#write(F, "valcodes|127;53|", str(val(concat(chr(127), "5")), 0, 3), "\n")
#write(F, "valcodes|1;53|", str(val(concat(chr(1), "5")), 0, 3), "\n")

// ---- #write of floats and vectors ----------------------------------------------------------------
Write("1.5") Write("0.3333333333333333") Write("1e300") Write("-0") Write("123456789") Write("1e-7")
Write("inf") Write("-inf") Write("nan") Write("0.1") Write("100000") Write("1000000")
Write("1234567.5") Write("-1e15") Write("1e16") Write("0.0001") Write("0.00001") Write("123456")
Write("999999.5") Write("5")
WriteVec(3, "1", "2", "3", "", "") WriteVec(2, "0.3333333333333333", "2", "", "", "")
WriteVec(3, "-0", "1e300", "inf", "", "") WriteVec(4, "1", "2", "3", "4", "")
WriteVec(5, "1", "2", "3", "4", "5")

// ---- chr, asc, strlen, strupr, strlwr, substr, strcmp, concat -------------------------------------
Chr("65") Chr("1.9") Chr("0") Chr("-0.5") Chr("127") Chr("128") Chr("200") Chr("255") Chr("256")
Chr("960") Chr("65535")
Asc("ABC") Asc("") Asc(" x")
Strlen("ABC") Strlen("") Strlen("Hello There!")
Upr("Hello There! 123 abcxyz{}`~") Lwr("Hello There! ABCXYZ@[]")
UprCode("97") UprCode("122") UprCode("233") UprCode("255") UprCode("353")
LwrCode("65") LwrCode("90") LwrCode("201") LwrCode("913")
Substr("ABCDEFGHI", "4", "2") Substr("ABCDEFGHI", "1", "9") Substr("ABCDEFGHI", "9", "1")
Substr("ABCDEFGHI", "4", "0") Substr("ABCDEFGHI", "4.9", "2.9") Substr("ABCDEFGHI", "1", "0")
Substr("ABCDEFGHI", "0", "1") Substr("ABCDEFGHI", "0", "0") Substr("ABCDEFGHI", "0", "9")
Substr("ABCDEFGHI", "0", "10") Substr("ABCDEFGHI", "10", "0") Substr("ABCDEFGHI", "0.5", "1")
Substr("ABCDEFGHI", "-0.5", "1") Substr("ABCDEFGHI", "5", "5") Substr("", "1", "0")
Substr("", "0", "0") Substr("AB", "3", "0") Substr("AB", "2", "1")
Strcmp("ABC", "ABD") Strcmp("ABD", "ABC") Strcmp("abc", "ABC") Strcmp("ab", "abc")
Strcmp("abc", "abc") Strcmp("a", "z") Strcmp("", "") Strcmp("", "a")
#write(F, "strcmpcodes|960|97|", str(strcmp(chr(960), "a"), 0, 0), "\n")
#write(F, "strcmpcodes||960|", str(strcmp("", chr(960)), 0, 0), "\n")
#write(F, "concat|a|", concat("a"), "\n")
#write(F, "concat|a;b;c;d;e;f;g;h;i;j;k|", concat("a", "b", "c", "d", "e", "f", "g", "h", "i", "j", "k"), "\n")
#write(F, "concatlen|a;chr(0);b|", str(strlen(concat("a", chr(0), "b")), 0, 0), "\n")

// ---- datetime(D [, FORMAT]) ----------------------------------------------------------------------
DatetimeDefault("0") DatetimeDefault("1") DatetimeDefault("0.5") DatetimeDefault("-1")
DatetimeDefault("1.00001") DatetimeDefault("0.999999") DatetimeDefault("0.00001157")
DatetimeDefault("-0.00001157") DatetimeDefault("8766.25") DatetimeDefault("36524")
DatetimeDefault("-36524") DatetimeDefault("1e6") DatetimeDefault("2900000")
DatetimeDefault("2921939") DatetimeDefault("2921939.99999") DatetimeDefault("-219145")
DatetimeDefault("-219144.99999") DatetimeDefault("-219145.000001")
Datetime("0", "%Y/%m/%d %H-%M-%S %j %a %A %b %B %p %y %Z %z %%")
Datetime("0", "%c") Datetime("0", "%x %X %D %e %U %w %G %V %u %C %g %k")
Datetime("0", "abc") Datetime("0", "%H %q") Datetime("0", "%Za")
Datetime("0.25", "%I %l %P %r %R %T %h") Datetime("0.75", "%I %l %p %P")
Datetime("-219145", "%c %a %G %V %U") Datetime("0", "%Ey %Od %EC %O %E")
Datetime("0", "%-d %_d %010Y %^a %#a")
Datetime("8800.123", "%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A1234567")

#fclose F
