#version 3.7;
// Recover F(P) for hypercomplex function FN from inside() at max_iteration 2:
// P is inside iff |F(P) + c| <= 4, so along each axis of c the two boundary points average to -F_k.
#fopen F "out.txt" write
#macro In(C, P) #local Jx = julia_fractal { C hypercomplex FN max_iteration 2 precision 10 } inside(Jx, P) #end
#declare Pts = array[NP] { PTS };
#for (n,0,NP-1)
  #declare P=Pts[n];
  #write (F, vstr(3,P,",",0,17))
  #for (k,0,3)
    #declare E=<0,0,0,0>; #switch(k) #case(0) #declare E=<1,0,0,0>; #break #case(1) #declare E=<0,1,0,0>; #break #case(2) #declare E=<0,0,1,0>; #break #case(3) #declare E=<0,0,0,1>; #break #end
    #declare T=array[2];
    #for (s,0,1)
      #declare Sg=1-2*s;
      #declare A=0; #declare B=50;
      #if (In(<0,0,0,0>,P)) 
      #for (it,0,70)
        #declare M=(A+B)/2;
        #if (In(Sg*M*E,P)) #declare A=M; #else #declare B=M; #end
      #end
      #end
      #declare T[s]=Sg*(A+B)/2;
    #end
    #write (F, ",", str(-(T[0]+T[1])/2,0,15))
  #end
  #write (F,"\n")
#end
#fclose F
