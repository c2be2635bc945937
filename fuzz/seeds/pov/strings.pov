// Strings: every string function, escapes, comparisons, string identifiers and file_exists.
#declare S1 = "Hello, \"world\"\t\\ \n";
#declare S2 = concat(S1, str(3.14159, 0, 3), str(-2, 5, 0), chr(65), chr(9731));
#declare S3 = substr("ABCDEFG", 2, 3);
#declare S4 = strupr("abc");
#declare S5 = strlwr("ABC");
#declare S6 = vstr(3, <1, 2, 3>, ", ", 0, 2);
#declare S7 = datetime(now, "%Y-%m-%d");
#declare N1 = strlen(S2) + asc("A") + val("1.5e2") + strcmp("a", "b");
#declare N2 = file_exists("colors.inc") + file_exists("missing.inc");
#if (S3 = "BCD" & S4 != S5 & "a" < "b") #debug concat(S6, "\n") #end
#debug concat("str ", str(1e300, 0, -1), " ", str(1, -3, 20), "\n")
#declare Big = "";
#for (I, 1, 10) #declare Big = concat(Big, str(I, 0, 0), ","); #end
text { ttf "timrom.ttf" "Text" 0.1, 0 pigment { rgb 1 } }
