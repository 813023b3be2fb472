// side tool: minimal semiflows x>=0, A x = 0 (A: m x n from .mat), Farkas on the n variables,
// rank test mod p for minimal supports, min P*N pivot order. Prints counts per step.
#include <bits/stdc++.h>
using namespace std;
using u64 = uint64_t; using i64 = int64_t; using u128 = unsigned __int128;
constexpr u64 MOD = (1ull<<61)-1;
u64 mulm(u64 a,u64 b){u128 r=(u128)a*b; u64 lo=(u64)(r&MOD), hi=(u64)(r>>61); u64 s=lo+hi; if(s>=MOD)s-=MOD; return s;}
u64 powm(u64 a,u64 e){u64 r=1;while(e){if(e&1)r=mulm(r,a);a=mulm(a,a);e>>=1;}return r;}
u64 tom(i64 v){ i64 r=v%(i64)MOD; if(r<0) r+=MOD; return (u64)r;}
constexpr int W=8; // up to 512 vars
struct Bits{u64 w[W]={}; int cnt()const{int c=0;for(auto x:w)c+=__builtin_popcountll(x);return c;}};
struct Row{vector<i64> a; Bits s;};
int m,n; vector<vector<i64>> A; // A[row m][col n]
int main(int argc,char**argv){
  ifstream f(argv[1]); f>>m>>n; A.assign(m,vector<i64>(n));
  for(int i=0;i<m;i++)for(int j=0;j<n;j++)f>>A[i][j];
  size_t limit = argc>2? stoull(argv[2]) : 50000000;
  // variables = columns of A (transitions); "a" of a row = A column restricted to remaining constraints
  vector<Row> R(n);
  for(int j=0;j<n;j++){R[j].a.resize(m);for(int i=0;i<m;i++)R[j].a[i]=A[i][j]; R[j].s.w[j/64]|=1ull<<(j%64);}
  vector<bool> done(m,false); vector<int> proc;
  for(int step=0;;step++){
    int best=-1; u64 bc=~0ull; 
    for(int i=0;i<m;i++){ if(done[i])continue; u64 p=0,q=0; for(auto&r:R){ if(r.a[i]>0)p++; else if(r.a[i]<0)q++; }
      if(p+q==0){done[i]=true;continue;} u64 c=p*q; if(c<bc||(c==bc&&false)){bc=c;best=i;} }
    if(best<0)break;
    int j=best; done[j]=true; proc.push_back(j);
    vector<int> P,N; vector<Row> out;
    for(int k=0;k<(int)R.size();k++){ if(R[k].a[j]>0)P.push_back(k); else if(R[k].a[j]<0)N.push_back(k); }
    for(size_t k=0;k<R.size();k++) if(R[k].a[j]==0) out.push_back(R[k]);
    size_t kept0=out.size();
    unordered_set<string> seen;
    vector<int> idx; vector<vector<u64>> M;
    for(int p:P)for(int q:N){
      Bits u; for(int w=0;w<W;w++)u.w[w]=R[p].s.w[w]|R[q].s.w[w];
      int sz=u.cnt(); if(sz-1>(int)proc.size())continue;
      // rank test mod p of A[S, proc]
      idx.clear(); for(int w=0;w<W;w++){u64 x=u.w[w];while(x){int b=__builtin_ctzll(x);idx.push_back(w*64+b);x&=x-1;}}
      M.assign(sz, vector<u64>(proc.size()));
      for(int a=0;a<sz;a++)for(size_t c=0;c<proc.size();c++)M[a][c]=tom(A[proc[c]][idx[a]]);
      int rank=0; for(size_t c=0;c<proc.size()&&rank<sz;c++){ int piv=-1; for(int a=rank;a<sz;a++)if(M[a][c]){piv=a;break;} if(piv<0)continue; swap(M[piv],M[rank]); u64 inv=powm(M[rank][c],MOD-2);
        for(int a=rank+1;a<sz;a++){ if(!M[a][c])continue; u64 fct=mulm(M[a][c],inv); for(size_t cc=c;cc<proc.size();cc++){ M[a][cc]=(M[a][cc]+MOD-mulm(fct,M[rank][cc]))%MOD; } } rank++; }
      if(rank!=sz-1)continue;
      string key((char*)u.w,sizeof(u.w)); if(!seen.insert(key).second)continue;
      Row r; r.s=u; r.a.resize(m); i64 cx=-R[q].a[j], cz=R[p].a[j]; i64 g=gcd(cx,cz); cx/=g;cz/=g;
      i64 gg=0; for(int i=0;i<m;i++){ r.a[i]=cx*R[p].a[i]+cz*R[q].a[i]; gg=gcd(gg,r.a[i]); }
      if(gg>1) for(auto&v:r.a)v/=gg; // note: support-only tracking; weights not needed for counting
      out.push_back(std::move(r));
      if(out.size()>limit){ printf("too many at step %d\n",step); return 1; }
    }
    fprintf(stderr,"step %d col %d P %zu N %zu kept %zu new %zu rows %zu\n",step,j,P.size(),N.size(),kept0,out.size()-kept0,out.size());
    R.swap(out);
  }
  printf("rays %zu\n",R.size());
  // write supports
  if(argc>3){ ofstream o(argv[3]); for(auto&r:R){ for(int j=0;j<n;j++) if(r.s.w[j/64]>>(j%64)&1) o<<j<<' '; o<<'\n'; } }
}
