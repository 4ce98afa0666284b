using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Surfaces;

/// <summary>A point or direction in double precision, metres; only what a cast's arithmetic needs.</summary>
internal readonly record struct D3(double X, double Y, double Z)
{
    public static D3 operator +(D3 a, D3 b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

    public static D3 operator -(D3 a, D3 b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

    public static D3 operator -(D3 a) => new(-a.X, -a.Y, -a.Z);

    public static D3 operator *(D3 a, double s) => new(a.X * s, a.Y * s, a.Z * s);

    public static double Dot(D3 a, D3 b) => (a.X * b.X) + (a.Y * b.Y) + (a.Z * b.Z);

    public static D3 Cross(D3 a, D3 b) => new((a.Y * b.Z) - (a.Z * b.Y), (a.Z * b.X) - (a.X * b.Z), (a.X * b.Y) - (a.Y * b.X));

    public double Length => Math.Sqrt(Dot(this, this));

    public Vector3 ToVector3() => new((float)X, (float)Y, (float)Z);

    /// <summary>
    /// The plane of polygon <paramref name="v"/> (in winding order): its Newell normal (not normalised: its length is
    /// twice the area), robust to collinear vertices, and the sum of its vertices (÷ their count: the mean it passes through).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // (on every polygon a cast tests)
    public static (D3 Normal, D3 Sum) Newell(ReadOnlySpan<D3> v)
    {
        double nx = 0, ny = 0, nz = 0, cx = 0, cy = 0, cz = 0;
        for (int i = 0, j = v.Length - 1; i < v.Length; j = i++)
        {
            nx += (v[j].Y - v[i].Y) * (v[j].Z + v[i].Z);
            ny += (v[j].Z - v[i].Z) * (v[j].X + v[i].X);
            nz += (v[j].X - v[i].X) * (v[j].Y + v[i].Y);
            (cx, cy, cz) = (cx + v[i].X, cy + v[i].Y, cz + v[i].Z);
        }

        return (new D3(nx, ny, nz), new D3(cx, cy, cz));
    }
}
