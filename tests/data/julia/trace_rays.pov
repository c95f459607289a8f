#version 3.7;
#declare J = julia_fractal { CC ALG FN max_iteration MI precision PR }
#fopen F "out.txt" write
#declare S=seed(11);
#for (i,0,NR-1)
  #declare O=<-1.5+3*rand(S), -1.5+3*rand(S), -5>;
  #declare D=<0.3*(rand(S)-0.5), 0.3*(rand(S)-0.5), 1>;
  #declare Nrm=<0,0,0>;
  #declare H=trace(J,O,D,Nrm);
  #write (F, vstr(3,O,",",0,17), ",", vstr(3,D,",",0,17), ",", vstr(3,H,",",0,17), ",", vstr(3,Nrm,",",0,17), "\n")
#end
#fclose F
