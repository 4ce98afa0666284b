using System.Numerics;

namespace AcDream.App.Scenes;

/// <summary>
/// A pointer ray of a scene (<c>"pointers"</c>): cast once, after a leg's last frame, from a fixed point towards another,
/// as click-to-walk or targeting would (<see cref="Movement.Pointer"/>); the summary prints what it met.
/// </summary>
/// <param name="Name">Shown in the summary.</param>
/// <param name="AfterLeg">The leg (1-based) after whose last frame it is cast, against the movers as that frame saw them.</param>
/// <param name="From">Where the ray starts, world metres: an outdoor point (its outdoor cell is worked out from it).</param>
/// <param name="Towards">A point it passes through, world metres; the ray goes on past it to <see cref="Movement.Pointer.MaxLength"/>.</param>
internal sealed record ScenePointer(string Name, int AfterLeg, Vector3 From, Vector3 Towards);
