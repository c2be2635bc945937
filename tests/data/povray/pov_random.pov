// Measures POV-Ray 3.7's seed()/rand() streams for tests/pov_random_test.cpp.
// Run in this folder:  povray +Ipov_random.pov +W1 +H1 -D -F   (writes pov_random.txt)
//
// Output lines:
//   stream NAME SEED       a stream made by seed(SEED)
//   NAME VALUE             the next rand() of stream NAME, str(V, 0, 30): exact enough to give
//                          back the double (every nonzero value is at least 1/(2^32-1))
//   sum NAME COUNT STATES VALUES
//                          COUNT more values of NAME: STATES = the sum of round(V·(2^32−1)) (exact
//                          integers), VALUES = the values summed in order in double
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location -z look_at 0 }
sphere { 0, 1 }

#fopen F "pov_random.txt" write

#macro Stream(Name, Seed)
  #declare Streams[Name] = seed(Seed);
  #write(F, "stream ", Names[Name], " ", str(Seed, 0, 6), "\n")
#end
#macro Draw(Name, Count)
  #local I = 0;
  #while (I < Count)
    #write(F, Names[Name], " ", str(rand(Streams[Name]), 0, 30), "\n")
    #local I = I + 1;
  #end
#end
#macro Sum(Name, Count)
  #local I = 0;
  #local States = 0;
  #local Values = 0;
  #while (I < Count)
    #local V = rand(Streams[Name]);
    #local States = States + floor(V * 4294967295 + 0.5);
    #local Values = Values + V;
    #local I = I + 1;
  #end
  #write(F, "sum ", Names[Name], " ", str(Count, 0, 0), " ", str(States, 0, 0), " ", str(Values, 0, 30), "\n")
#end

#declare Names = array[15] { "s0", "s1", "sm1", "s42", "s12345", "s2p31", "s1p5", "sm2p5",
                             "s0p999", "s1e10", "sm2p31m1", "s2p32p1", "P", "Q", "R" }
#declare Streams = array[15]
#declare Seeds = array[12] { 0, 1, -1, 42, 12345, 2147483648, 1.5, -2.5, 0.999, 1e10,
                             -2147483649, 4294967297 }

// Forty values from each seed, then 10000 more summed.
#declare K = 0;
#while (K < 12)
  Stream(K, Seeds[K])
  Draw(K, 40)
  Sum(K, 10000)
  #declare K = K + 1;
#end

// Streams interleaved: P and Q share a seed and must not share a state; R is drawn twice as often.
Stream(12, 3) Stream(13, 3) Stream(14, -7)
#declare I = 0;
#while (I < 60)
  Draw(12, 1)
  #if (mod(I, 3) = 0) Draw(13, 1) #end
  Draw(14, 2)
  #declare I = I + 1;
#end

#fclose F
