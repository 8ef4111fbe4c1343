NDIM = 2, IPS = 4, ICP = ['T', 11], UZR = {'T': [1.0, 2.0d0], 5: -1e-3}, UZSTOP = {'L': 3}
THL = {'T': 0.0}, PAR = {'Delta': 0.005, 'Ltot': 1.98889}
parnames = {1: 'a', 2: 'b'}
unames = {1: 'x'}
DS = '-', NTST = 40 ! comment
