C     The planar elastica theta'' + P sin(theta) = 0 on [0,1] with
C     theta'(0) = theta'(1) = 0 (fixed-form Fortran 77, AUTO's style).
C     PAR(1) = P.  The straight rod theta = 0 is a solution for every P;
C     its branch points are at P = (n pi)**2.
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER NDIM, ICP(*), IJAC
      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM)
      DOUBLE PRECISION DFDU(NDIM,*), DFDP(NDIM,*)
      F(1) = U(2)
      F(2) = -PAR(1)*SIN(U(1))
      END

      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER NDIM
      DOUBLE PRECISION U(NDIM), PAR(*), T
      PAR(1) = 1.0D0
      U(1) = 0.0D0
      U(2) = 0.0D0
      END

      SUBROUTINE BCND(NDIM,PAR,ICP,NBC,U0,U1,FB,IJAC,DBC)
      IMPLICIT NONE
      INTEGER NDIM, ICP(*), NBC, IJAC
      DOUBLE PRECISION PAR(*), U0(NDIM), U1(NDIM), FB(NBC), DBC(NBC,*)
      FB(1) = U0(2)
      FB(2) = U1(2)
      END

      SUBROUTINE ICND
      END

      SUBROUTINE FOPT
      END

      SUBROUTINE PVLS
      END
