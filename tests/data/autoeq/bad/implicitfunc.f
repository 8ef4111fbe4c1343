C     Bratu's problem with an implicitly typed FUNC: U, PAR and F are REAL
C     (single precision), so FUNC would read AUTO's DOUBLE PRECISION numbers
C     as other numbers.  AUTO compiles it and computes nonsense; cable
C     refuses it.
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      DIMENSION U(NDIM), PAR(*), F(NDIM)
      F(1) = U(2)
      F(2) = -PAR(1)*EXP(U(1))
      RETURN
      END

      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT DOUBLE PRECISION (A-H,O-Z)
      DIMENSION U(NDIM), PAR(*)
      PAR(1) = 0.0D0
      U(1) = 0.0D0
      U(2) = 0.0D0
      RETURN
      END

      SUBROUTINE BCND(NDIM,PAR,ICP,NBC,U0,U1,FB,IJAC,DBC)
      IMPLICIT DOUBLE PRECISION (A-H,O-Z)
      DIMENSION PAR(*), U0(NDIM), U1(NDIM), FB(NBC), DBC(NBC,*)
      FB(1) = U0(1)
      FB(2) = U1(1)
      RETURN
      END

      SUBROUTINE ICND
      END

      SUBROUTINE FOPT
      END

      SUBROUTINE PVLS
      END
