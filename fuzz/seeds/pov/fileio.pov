// File I/O: #fopen write/append/read, #write of every value kind, #read back, #fclose,
// defined() on a file at its end.
#fopen Out "data.txt" write
#write (Out, 1.5, ",", <1, 2, 3>, ",", "\"quoted\"", "\n")
#write (Out, -7, ",", <0.5, 0.25>, ",\n")
#fclose Out
#fopen App "data.txt" append
#write (App, "\"appended\"\n")
#fclose App
#fopen In "data.txt" read
#read (In, A, B, C)
#read (In, D, E)
#read (In, G)
#if (defined(In)) #read (In, H) #end
#fopen Bin "data.bin" write
#write (Bin, uint8 65, uint16be 256, sint32le -1)
#fclose Bin
#debug concat(str(A, 0, 2), vstr(3, B, " ", 0, 0), C, "\n")
#include "colors.inc"
#declare Exists = file_exists("data.txt");
