#version 3.7;
#declare J = julia_fractal { CC hypercomplex FN max_iteration MI precision 10 }
#fopen F "out.txt" write
#declare S=seed(7);
#for (i,0,9999)
  #declare P=<-2.5+5*rand(S), -2.5+5*rand(S), -2.5+5*rand(S)>;
  #write (F, vstr(3,P,",",0,17), ",", inside(J,P), "\n")
#end
#fclose F
