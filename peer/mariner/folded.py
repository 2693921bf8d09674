"""The Mariner's folded table integrated as it stands, in the form of public manoeuvring codes
(Fossen's Marine Systems Simulator, mariner.m): the rigid-body terms stay in the coefficients,
so the sway equation carries -m'(1 + u')r' where 4.46 has -M u r, i.e. u/U taken as 1 + u'.

    python3 peer/mariner/folded.py

prints the 35 degree turning circle's advance, transfer and tactical diameter (RK4, 0.05 s,
crossings by linear interpolation) beside which `eom run scenes/mariner.toml` gives the same
figures for the converted table; the difference is that approximation, as the ship slows in
the turn. Reads the published table, data/mariner.json.
"""
import json, math, os
here = os.path.dirname(os.path.abspath(__file__))
d = json.load(open(os.path.join(here, '..', '..', 'data', 'mariner.json')))
c=d['coefficients_prime']; L=d['length_m']; U0=d['design_speed_m_s']
m=d['mass_prime']['m']; Iz=d['mass_prime']['Iz']; xG=d['mass_prime']['xG']
g=lambda k: c[k]
m11=m-g('Xudot'); m22=m-g('Yvdot'); m23=m*xG-g('Yrdot'); m32=m*xG-g('Nvdot'); m33=Iz-g('Nrdot')
def f(x, dc):
    du,vv,rr,X_,Y_,psi,delta=x
    U=math.sqrt((U0+du)**2+vv**2)
    u=du/U; v=vv/U; r=rr*L/U
    dd=max(-math.radians(40),min(math.radians(40),dc))-delta
    dd=max(-math.radians(5),min(math.radians(5),dd))
    X=(g('Xu')*u+g('Xuu')*u**2+g('Xuuu')*u**3+g('Xvv')*v**2+g('Xrr')*r**2+g('Xrv')*r*v+g('Xdd')*delta**2+g('Xudd')*u*delta**2+g('Xvd')*v*delta+g('Xuvd')*u*v*delta)
    Y=(g('Yv')*v+g('Yr')*r+g('Yvvv')*v**3+g('Yvvr')*v**2*r+g('Yvu')*v*u+g('Yru')*r*u+g('Yd')*delta+g('Yddd')*delta**3+g('Yud')*u*delta+g('Yuud')*u**2*delta+g('Yvdd')*v*delta**2+g('Yvvd')*v**2*delta+(g('Y0')+g('Y0u')*u+g('Y0uu')*u**2))
    N=(g('Nv')*v+g('Nr')*r+g('Nvvv')*v**3+g('Nvvr')*v**2*r+g('Nvu')*v*u+g('Nru')*r*u+g('Nd')*delta+g('Nddd')*delta**3+g('Nud')*u*delta+g('Nuud')*u**2*delta+g('Nvdd')*v*delta**2+g('Nvvd')*v**2*delta+(g('N0')+g('N0u')*u+g('N0uu')*u**2))
    det=m22*m33-m23*m32
    return [X*(U**2/L)/m11, -(-m33*Y+m23*N)*(U**2/L)/det, (-m32*Y+m22*N)*(U**2/L**2)/det,
            (math.cos(psi)*(U0/U+u)-math.sin(psi)*v)*U, (math.sin(psi)*(U0/U+u)+math.cos(psi)*v)*U, r*(U/L), dd]
def rk4(x,h,dc):
    k1=f(x,dc); k2=f([a+h/2*b for a,b in zip(x,k1)],dc); k3=f([a+h/2*b for a,b in zip(x,k2)],dc); k4=f([a+h*b for a,b in zip(x,k3)],dc)
    return [a+h/6*(b+2*cc+2*dd+e) for a,b,cc,dd,e in zip(x,k1,k2,k3,k4)]
x=[0,0,0,0,0,0,0]; h=0.05; t=0; prev=x
res={}
while t<1500:
    nx=rk4(x,h,math.radians(35)); t+=h
    for ang,key in [(math.pi/2,'90'),(math.pi,'180')]:
        if key not in res and abs(nx[5])>=ang:
            s=(ang-abs(x[5]))/(abs(nx[5])-abs(x[5]))
            res[key]=[a+s*(b-a) for a,b in zip(x,nx)]
    x=nx
U=math.sqrt((U0+x[0])**2+x[1]**2)
print('advance',res['90'][3],'transfer',abs(res['90'][4]),'tactical',abs(res['180'][4]),'R',U/abs(x[2]),'U',U)
