using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>A surface a move met.</summary>
/// <param name="Kind">What it is.</param>
/// <param name="Id">Whose it is: a cell id or an object's GfxObj/Setup id, as <paramref name="Kind"/> says; 0 with <see cref="SurfaceKind.None"/>.</param>
/// <param name="Normal">Its unit normal, world axes, pointing at the mover's side (a wall's is horizontal, as <see cref="ResolveResult.SurfaceNormal"/>); zero with <see cref="SurfaceKind.None"/>.</param>
public readonly record struct SurfaceContact(SurfaceKind Kind, uint Id, Vector3 Normal);
