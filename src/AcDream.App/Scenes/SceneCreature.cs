using System.Numerics;

namespace AcDream.App.Scenes;

/// <summary>
/// A creature of a scene (<c>"creatures"</c>): a cylinder of the game's human size that appears at its home when the
/// home's landblock loads and, when it wanders, walks about it with intents drawn from its own seed.
/// </summary>
/// <param name="Home">Where it appears, world metres; it stands on the ground there.</param>
/// <param name="Wander">How far from home it walks, metres; 0: it stands where it appeared.</param>
/// <param name="Seed">The seed of its intents (<see cref="Random(int)"/>).</param>
internal sealed record SceneCreature(Vector2 Home, float Wander, int Seed);
